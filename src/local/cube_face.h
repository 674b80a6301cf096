#pragma once
// Which face of a cube map a direction D lands on, and where: the rule of the OpenGL 3.3 core
// specification, table 3.21 (8.19 in 4.x). The CPU twins of the shadow and reflection cube maps
// look texels up with it exactly as the GPU does.
#include <glm/vec3.hpp>

namespace luz {

struct CubeFacePoint {
  int face = 0;    // 0..5 in GL's order: +X, -X, +Y, -Y, +Z, -Z
  float s = 0.0f;  // 0..1 across the face
  float t = 0.0f;  // 0..1 down the face
};

CubeFacePoint cube_face_point(const glm::vec3& D);

}  // namespace luz
