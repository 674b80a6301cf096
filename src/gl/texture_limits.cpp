#include "gl/texture_limits.h"

#include <algorithm>
#include <bit>

namespace luz::gl {

int power_of_two_below(int side) { return side > 1 ? int(std::bit_floor(unsigned(side - 1))) : 0; }

int largest_square_array(GLenum internal_format, GLenum format, GLenum type, int layers, int wanted) {
  GLint max_texture = 0, max_layers = 0, max_renderbuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  if (layers > max_layers) return 0;
  const auto fits = [&](int side) {
    if (!glGetTexLevelParameteriv) return true;  // OpenGL ES has no proxy textures: the limits alone
    glTexImage3D(GL_PROXY_TEXTURE_2D_ARRAY, 0, GLint(internal_format), side, side, layers, 0, format,
                 type, nullptr);
    GLint width = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_WIDTH, &width);
    return width == side;
  };
  const int side = std::min({wanted, int(max_texture), int(max_renderbuffer)});
  if (side >= 1 && fits(side)) return side;
  for (int smaller = power_of_two_below(side); smaller >= 1; smaller /= 2)
    if (fits(smaller)) return smaller;
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
  while (side >= 1 && !allocate_array(internal_format, format, type, side, layers))
    side = power_of_two_below(side);
  glBindTexture(GL_TEXTURE_2D_ARRAY, GLuint(previous));
  glDeleteTextures(1, &scratch);
  return side;
}

}  // namespace luz::gl
