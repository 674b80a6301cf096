#pragma once
// Which GLSL the shaders of shaders/ are compiled as (DESIGN.md "Two targets"). They are written
// once, in GLSL 330 core, each opening with `#version 330 core`; for an OpenGL ES 3 context
// (WebGL 2 in the page) that line is replaced by glsl_header(es_300): `#version 300 es`, the
// precision every float, int and sampler type gets, and `#define LUZ_GLSL_ES 1` for the few
// lines that differ. Both dialects give the same pictures where both compile: highp is the
// desktop's 32-bit float and int.
#include <optional>
#include <string>

namespace luz::gl {

enum class GlslDialect { desktop_330, es_300 };

const char* to_string(GlslDialect dialect);

// The dialect of the context current on this thread (its GL_VERSION starts "OpenGL ES" for
// ES), unless set_glsl_dialect chose one: the tests compile the page's GLSL ES on the desktop's
// Mesa that way (a 4.3+ core context takes both, ARB_ES3_compatibility).
GlslDialect current_glsl_dialect();
void set_glsl_dialect(std::optional<GlslDialect> dialect);

// The line(s) that open a stage in `dialect`; `file_version` is the file's own #version line,
// the header of desktop_330.
std::string glsl_header(GlslDialect dialect, const std::string& file_version);

}  // namespace luz::gl
