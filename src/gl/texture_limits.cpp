#include "gl/texture_limits.h"

#include <algorithm>

namespace luz::gl {

int largest_square_array(GLenum internal_format, GLenum format, GLenum type, int layers, int wanted) {
  GLint max_texture = 0, max_layers = 0, max_renderbuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  if (layers > max_layers) return 0;
  for (int side = std::min({wanted, int(max_texture), int(max_renderbuffer)}); side >= 1; side /= 2) {
    glTexImage3D(GL_PROXY_TEXTURE_2D_ARRAY, 0, GLint(internal_format), side, side, layers, 0, format,
                 type, nullptr);
    GLint width = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_WIDTH, &width);
    if (width == side) return side;
  }
  return 0;
}

bool allocate_array(GLenum internal_format, GLenum format, GLenum type, int side, int layers) {
  while (glGetError() != GL_NO_ERROR) {
  }
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GLint(internal_format), side, side, layers, 0, format, type, nullptr);
  return glGetError() != GL_OUT_OF_MEMORY;
}

int largest_allocatable_square_array(GLenum internal_format, GLenum format, GLenum type, int layers,
                                     int wanted) {
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previous);
  GLuint scratch = 0;
  glGenTextures(1, &scratch);
  glBindTexture(GL_TEXTURE_2D_ARRAY, scratch);
  int side = largest_square_array(internal_format, format, type, layers, wanted);
  while (side >= 1 && !allocate_array(internal_format, format, type, side, layers)) side /= 2;
  glBindTexture(GL_TEXTURE_2D_ARRAY, GLuint(previous));
  glDeleteTextures(1, &scratch);
  return side;
}

}  // namespace luz::gl
