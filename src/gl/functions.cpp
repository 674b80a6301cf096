#include "gl/functions.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz {

using i18n::tr;
using i18n::trf;

#define LUZ_GL(type, name) type name = nullptr;
#include "gl/function_list.h"
#undef LUZ_GL

namespace {

// Desktop functions OpenGL ES 3 (WebGL 2) does not have. On an ES context they stay null: the
// code that calls them asks first (texture_limits.cpp) or runs on the desktop only (the window's
// draw buffer, radiosity's wireframe).
constexpr std::array<std::string_view, 5> kDesktopOnly = {"glPolygonMode", "glGetTexImage", "glDrawBuffer",
                                                          "glGetTexLevelParameteriv", "glClearDepth"};

bool context_is_es() {
  const GLubyte* version = glGetString ? glGetString(GL_VERSION) : nullptr;
  return version && std::strncmp(reinterpret_cast<const char*>(version), "OpenGL ES", 9) == 0;
}

}  // namespace

void load_gl_functions(GlResolver resolve) {
  std::vector<std::string> missing;
  // A void (*)() converts to any other function pointer type; the resolver knows the real one.
#define LUZ_GL(type, name)                        \
  name = reinterpret_cast<type>(resolve(#name));  \
  if (!name) missing.push_back(#name);
#include "gl/function_list.h"
#undef LUZ_GL
  if (context_is_es())
    std::erase_if(missing, [](const std::string& name) {
      return std::find(kDesktopOnly.begin(), kDesktopOnly.end(), name) != kDesktopOnly.end();
    });
  if (!missing.empty())
    throw Error(ErrorKind::gl, trf("the OpenGL context lacks {} of the 3.3 core functions Luz needs: {}",
                                   missing.size(), fmt::join(missing, ", ")));
}

const char* gl_version_string() {
  if (!glGetString) return tr("(no OpenGL functions loaded)");
  const GLubyte* version = glGetString(GL_VERSION);
  const GLubyte* renderer = glGetString(GL_RENDERER);
  static thread_local std::string text;
  text = fmt::format("{}, {}", version ? reinterpret_cast<const char*>(version) : "?",
                     renderer ? reinterpret_cast<const char*>(renderer) : "?");
  return text.c_str();
}

}  // namespace luz
