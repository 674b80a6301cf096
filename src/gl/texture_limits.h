#pragma once
// What the current context can allocate, asked before allocating: a texture the driver cannot
// hold otherwise shows up later as an "incomplete framebuffer", far from its cause.
#include "gl/functions.h"

namespace luz::gl {

// `wanted` itself, or else the largest power of two below it, for which an s x s x `layers` 2D array
// texture of `internal_format` (with `format`, `type` for the proxy upload) and an s x s
// renderbuffer fit this context: GL_MAX_TEXTURE_SIZE, GL_MAX_ARRAY_TEXTURE_LAYERS,
// GL_MAX_RENDERBUFFER_SIZE and the driver's proxy-texture answer (which knows its memory
// limits: llvmpipe refuses more than 1 GB in one texture). 0 when not even 1 x 1 fits.
int largest_square_array(GLenum internal_format, GLenum format, GLenum type, int layers, int wanted);

// Allocates the array texture bound to GL_TEXTURE_2D_ARRAY (glTexImage3D without data); false
// when the driver answers GL_OUT_OF_MEMORY, which some (llvmpipe) do even where the proxy said
// yes. Clears earlier errors first.
bool allocate_array(GLenum internal_format, GLenum format, GLenum type, int side, int layers);

// The largest power of two below `side` (0 for 1): shadow and item-buffer sizes to suggest when
// `side` does not fit are powers of two, the sizes GPUs and the slides use.
int power_of_two_below(int side);

// `wanted`, or else the largest power of two below it, that allocate_array really allocates, tried on a
// scratch texture that is deleted again: the number to suggest after a failed allocation.
int largest_allocatable_square_array(GLenum internal_format, GLenum format, GLenum type, int layers,
                                     int wanted);

}  // namespace luz::gl
