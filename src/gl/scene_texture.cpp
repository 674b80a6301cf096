#include "gl/scene_texture.h"

#include <vector>

#include "gl/glsl_dialect.h"

namespace luz::gl {

namespace {

// The texels with an alpha of 1, for a four-channel format.
std::vector<float> with_alpha(const Texture& texture) {
  std::vector<float> rgba;
  rgba.reserve(texture.texels.size() * 4);
  for (const Rgb& texel : texture.texels) rgba.insert(rgba.end(), {texel.r, texel.g, texel.b, 1.0f});
  return rgba;
}

}  // namespace

// The texels are sRGB-decoded by the loader, so they go up as floats, not as an sRGB format that
// GL would decode a second time. OpenGL ES 3 (WebGL 2, the page) makes mipmaps only of a format it
// can both filter and draw into, which RGB32F is not there (the mipmaps left undone, every texel
// reads black): it gets RGBA16F, drawn into through EXT_color_buffer_float (the page requires it),
// whose half floats hold the texels within 0.05%.
GLuint upload_texture(const Texture& texture) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Row 0 = the top = glTF's v = 0, as GL's t = 0.
  if (current_glsl_dialect() == GlslDialect::es_300)
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, texture.width, texture.height, 0, GL_RGBA, GL_FLOAT,
                 with_alpha(texture).data());
  else
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, texture.width, texture.height, 0, GL_RGB, GL_FLOAT,
                 texture.texels.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  return id;
}

}  // namespace luz::gl
