// A command that reaches into the window: the check must refuse it.
#include "app/viewer/panel.h"
