#include "gl/functions.h"

#include <string>
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

void load_gl_functions(GlResolver resolve) {
  std::vector<std::string> missing;
  // A void (*)() converts to any other function pointer type; the resolver knows the real one.
#define LUZ_GL(type, name)                        \
  name = reinterpret_cast<type>(resolve(#name));  \
  if (!name) missing.push_back(#name);
#include "gl/function_list.h"
#undef LUZ_GL
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
