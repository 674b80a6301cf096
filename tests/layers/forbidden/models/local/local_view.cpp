// A model view that includes the Viewer and GLFW: the check must refuse both.
#include <GLFW/glfw3.h>
#include "app/viewer/viewer.h"
