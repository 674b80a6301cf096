#include "gl/scene_texture.h"

namespace luz::gl {

// The texels are sRGB-decoded by the loader, so they go up as float RGB, not as an sRGB format
// that GL would decode a second time.
GLuint upload_texture(const Texture& texture) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, texture.width, texture.height, 0, GL_RGB, GL_FLOAT,
               texture.texels.data());  // row 0 = the top = glTF's v = 0, as GL's t = 0
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  return id;
}

}  // namespace luz::gl
