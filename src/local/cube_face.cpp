#include "local/cube_face.h"

#include <glm/common.hpp>

namespace luz {

CubeFacePoint cube_face_point(const glm::vec3& D) {
  // The major axis picks the face; sc and tc are the coordinates on it, divided by that axis.
  const glm::vec3 a = glm::abs(D);
  int face = 0;
  float sc = 0.0f, tc = 0.0f, ma = 1.0f;
  if (a.x >= a.y && a.x >= a.z) {
    face = D.x >= 0.0f ? 0 : 1;
    sc = D.x >= 0.0f ? -D.z : D.z;
    tc = -D.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = D.y >= 0.0f ? 2 : 3;
    sc = D.x;
    tc = D.y >= 0.0f ? D.z : -D.z;
    ma = a.y;
  } else {
    face = D.z >= 0.0f ? 4 : 5;
    sc = D.z >= 0.0f ? D.x : -D.x;
    tc = -D.y;
    ma = a.z;
  }
  return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

}  // namespace luz
