#pragma once
// The sdf_morph studio environment (the seed's reflection probe made analytic), one template for
// the scalar path (glm::vec3 directions) and the eight-lane path (V3x8): the same operations in
// the same order, so every lane has the scalar bits.
#include <glm/glm.hpp>

#include "scenes/sdf_morph/uniforms.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel::sdf_morph {

// ---- studio look (linear Rec.709) ----
inline const glm::vec3 WALL_LOW(0.16f, 0.155f, 0.15f);    // walls near the horizon
inline const glm::vec3 WALL_HIGH(0.03f, 0.032f, 0.036f);  // towards the ceiling
inline const glm::vec3 FLOOR_FAR(0.085f, 0.08f, 0.075f);  // below the horizon
constexpr float WALL_GRADIENT_TOP = 0.6f;                 // d.y where the wall reaches WALL_HIGH
constexpr float HORIZON_SOFTNESS = 0.04f;  // d.y half width of the floor/wall transition
// Light pool on the wall behind the object, falling off as cos^6 from BACKDROP_DIR.
inline const glm::vec3 BACKDROP_DIR(0.0f, 0.148340f, 0.988936f);
inline const glm::vec3 BACKDROP_GLOW(0.22f, 0.21f, 0.19f);
constexpr float SOFTBOX_MIN_COS = 0.05f;      // boxes are invisible beyond ~87 degrees off-axis
constexpr float SOFTBOX_EDGE = 0.02f;         // soft edge width on the unit-distance plane
constexpr float SOFTBOX_GLOW = 0.04f;         // faint halo around each box (diffuser spill)
constexpr float SOFTBOX_GLOW_FALLOFF = 8.0f;  // halo: 1 / (1 + (falloff * distance)^2)

// dm::mix of two colours by a scalar or per-lane weight.
inline glm::vec3 mixColor(const glm::vec3& x, const glm::vec3& y, float a) {
  return dm::mix(x, y, a);
}
inline V3x8 mixColor(const glm::vec3& x, const glm::vec3& y, F8 a) {
  return x * (1.0f - a) + y * a;
}
inline V3x8 mixColor(const glm::vec3& x, const V3x8& y, F8 a) {
  return x * (1.0f - a) + y * a;
}
inline glm::vec3 selectColor(bool m, const glm::vec3& a, const glm::vec3& b) {
  return m ? a : b;
}
inline V3x8 selectColor(M8 m, const V3x8& a, const V3x8& b) {
  return select(m, a, b);
}
inline glm::vec3 blackLike(const glm::vec3&) {
  return glm::vec3(0.0f);
}
inline V3x8 blackLike(const V3x8&) {
  return V3x8(glm::vec3(0.0f));
}

// sdRoundRect of sdf/sdf.h (sdBox2 of b - r, minus r) over glm::vec2 or V2x8.
template <class V2>
inline auto roundRect(const V2& p, const glm::vec2& b, float r) {
  const V2 q = vabs(p) - (b - glm::vec2(r));
  return vlength(vmax(q, 0.0f)) + dm::min(dm::max(q.x, q.y), 0.0f) - r;
}

// A soft box as seen in direction d: its rounded rectangle on the unit-distance plane with a
// soft edge and a faint halo. Lanes facing away skip it only when all of them do.
template <class V>
inline V softBox(const V& d, const SoftBox& box) {
  const auto c = vdot(d, box.dir);
  const auto hidden = c <= SOFTBOX_MIN_COS;
  if (all(hidden)) return blackLike(d);
  const auto uv = vec2_of(vdot(d, box.u), vdot(d, box.v)) / c;
  const auto sd = roundRect(uv, box.half_size, box.corner);
  const auto core = 1.0f - dm::smoothstep(-SOFTBOX_EDGE, SOFTBOX_EDGE, sd);
  const auto g = SOFTBOX_GLOW_FALLOFF * dm::max(sd, 0.0f);
  const auto glow = SOFTBOX_GLOW / (1.0f + g * g);
  return selectColor(hidden, blackLike(d), box.radiance * (core + glow));
}

// Studio radiance seen in direction d (unit): gradient walls, a light pool on the backdrop and
// the soft boxes. Analytic, at infinity, like a reflection probe.
template <class V>
inline V studio(const V& d, const MorphUniforms& u) {
  const V wall = mixColor(WALL_LOW, WALL_HIGH, dm::smoothstep(0.0f, WALL_GRADIENT_TOP, d.y));
  V col = mixColor(FLOOR_FAR, wall, dm::smoothstep(-HORIZON_SOFTNESS, HORIZON_SOFTNESS, d.y));
  const auto b = dm::max(vdot(d, BACKDROP_DIR), 0.0f);
  const auto b2 = b * b;
  col = col + BACKDROP_GLOW * (b2 * b2 * b2);
  for (int i = 0; i < SOFTBOX_COUNT; ++i) col = col + softBox(d, u.boxes[i]);
  return col * u.env_intensity;
}

}  // namespace sdfreel::sdf_morph
