// Tests that compile the shaders as GLSL ES on the desktop's Mesa (the page's dialect).
#pragma once

#include <optional>

#include "gl/glsl_dialect.h"

namespace luz {

// Compiles programs as the given dialect for the scope's lifetime.
class DialectScope {
public:
  explicit DialectScope(gl::GlslDialect dialect) { gl::set_glsl_dialect(dialect); }
  ~DialectScope() { gl::set_glsl_dialect(std::nullopt); }
  DialectScope(const DialectScope&) = delete;
  DialectScope& operator=(const DialectScope&) = delete;
};

}  // namespace luz
