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

const char* to_string(FogMode mode) {
  switch (mode) {
    case FogMode::off: return "off";
    case FogMode::linear: return "linear";
    case FogMode::exponential: return "exponential";
  }
  return "?";
}

}  // namespace luz
