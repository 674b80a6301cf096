#include "local/local_options.h"

namespace luz {

const char* to_string(Shading shading) {
  switch (shading) {
    case Shading::flat: return "flat";
    case Shading::gouraud: return "gouraud";
    case Shading::phong: return "phong";
  }
  return "?";
}

}  // namespace luz
