#pragma once
// The GL objects behind an offscreen framebuffer: one colour texture of a given format and a
// 32-bit float depth buffer. Framebuffer (float radiance) and ItemFramebuffer (patch IDs)
// differ only in the colour format, so both are made here.
#include <string>

#include "gl/functions.h"

namespace luz::gl {

struct ColourFormat {
  GLenum internal_format;  // e.g. GL_RGBA32F, GL_R32UI
  GLenum format;           // e.g. GL_RGBA, GL_RED_INTEGER
  GLenum type;             // e.g. GL_FLOAT, GL_UNSIGNED_INT
  const char* name;        // for messages: "RGBA32F"
};

struct RenderTarget {
  GLuint fbo = 0, colour = 0, depth = 0;

  // Throws luz::Error: bad_value for an empty size, gl when the driver cannot complete it.
  RenderTarget(int width, int height, const ColourFormat& format);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

private:
  void release();
};

}  // namespace luz::gl
