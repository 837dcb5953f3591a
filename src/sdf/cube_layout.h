#pragma once
// The GL cube map layout (the spec's major-axis table), shared by every cube sdfreel makes or
// samples on the CPU: faces +x, -x, +y, -y, +z, -z; on each, s and t in [-1, 1], t down the rows.
#include <glm/glm.hpp>

#include "sdf/det_math.h"

namespace sdfreel {

struct CubeFaceCoord {
  int face;
  float s, t;
};

// The face a direction leaves the cube through, and where on it.
inline CubeFaceCoord cube_face_of(const glm::vec3& d) {
  const float ax = dm::abs(d.x), ay = dm::abs(d.y), az = dm::abs(d.z);
  if (ax >= ay && ax >= az)
    return d.x > 0.0f ? CubeFaceCoord{0, -d.z / ax, -d.y / ax}
                      : CubeFaceCoord{1, d.z / ax, -d.y / ax};
  if (ay >= az)
    return d.y > 0.0f ? CubeFaceCoord{2, d.x / ay, d.z / ay}
                      : CubeFaceCoord{3, d.x / ay, -d.z / ay};
  return d.z > 0.0f ? CubeFaceCoord{4, d.x / az, -d.y / az}
                    : CubeFaceCoord{5, -d.x / az, -d.y / az};
}

// The (unnormalised) direction through (s, t) of `face`.
inline glm::vec3 cube_face_direction(int face, float s, float t) {
  switch (face) {
    case 0:
      return {1.0f, -t, -s};
    case 1:
      return {-1.0f, -t, s};
    case 2:
      return {s, 1.0f, t};
    case 3:
      return {s, -1.0f, -t};
    case 4:
      return {s, -t, 1.0f};
    default:
      return {-s, -t, -1.0f};
  }
}

}  // namespace sdfreel
