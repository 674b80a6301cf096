#include "gl/render_target.h"

#include <fmt/format.h>

#include "core/error.h"
#include "core/i18n.h"

namespace luz::gl {

using i18n::tr;
using i18n::trf;

RenderTarget::RenderTarget(int width, int height, const ColourFormat& format) {
  if (width <= 0 || height <= 0)
    throw Error(ErrorKind::bad_value, trf("{} target size {}x{} is empty", format.name, width, height));

  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(format.internal_format), width, height, 0, format.format,
               format.type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // read back texel for texel
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);

  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw Error(ErrorKind::gl, trf("a {}x{} {} framebuffer is incomplete (status 0x{:x}) on {}", width,
                                   height, format.name, status, gl_version_string()));
  }
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() {
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(1, &depth);
  glDeleteTextures(1, &colour);
}

}  // namespace luz::gl
