#pragma once
// A scene's kd texture on the GPU, as the local models and the radiosity picture sample it.
#include "core/scene.h"
#include "gl/functions.h"

namespace luz::gl {

// Uploads `texture` as a new GL_TEXTURE_2D (float RGB: the texels are already linear),
// trilinear and repeating; returns its name, which the caller deletes.
GLuint upload_texture(const Texture& texture);

}  // namespace luz::gl
