#include "gl/glsl_dialect.h"

#include <atomic>
#include <cstring>

#include "gl/functions.h"

namespace luz::gl {

namespace {

// -1: the context's; else a GlslDialect.
std::atomic<int> chosen{-1};

// GLSL ES 3.00 gives float and int a default precision only in some stages and samplers other
// than sampler2D and samplerCube none at all: every type the shaders use gets highp, the
// desktop's 32 bits.
constexpr const char* kEsHeader =
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "precision highp sampler2D;\n"
    "precision highp sampler2DArray;\n"
    "precision highp samplerCube;\n"
    "precision highp usampler2D;\n"
    "#define LUZ_GLSL_ES 1";

}  // namespace

const char* to_string(GlslDialect dialect) {
  return dialect == GlslDialect::es_300 ? "GLSL ES 3.00" : "GLSL 3.30 core";
}

GlslDialect current_glsl_dialect() {
  const int set = chosen.load();
  if (set >= 0) return GlslDialect(set);
  const GLubyte* version = glGetString ? glGetString(GL_VERSION) : nullptr;
  const bool es = version && std::strncmp(reinterpret_cast<const char*>(version), "OpenGL ES", 9) == 0;
  return es ? GlslDialect::es_300 : GlslDialect::desktop_330;
}

void set_glsl_dialect(std::optional<GlslDialect> dialect) { chosen = dialect ? int(*dialect) : -1; }

std::string glsl_header(GlslDialect dialect, const std::string& file_version) {
  return dialect == GlslDialect::es_300 ? kEsHeader : file_version;
}

}  // namespace luz::gl
