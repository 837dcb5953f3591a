#include "scenes/museum/probe.h"

#include "sdf/cube_layout.h"
#include "sdf/det_math.h"

namespace sdfreel::museum {
namespace {

using glm::vec3;

// The nearest box the ray o + d t (t > 0) enters, its t and the entered face's normal.
bool hit_boxes(const vec3& o, const vec3& d, const std::vector<HallBox>& boxes, size_t& which,
               float& t_hit, vec3& normal) {
  t_hit = 1e30f;
  bool hit = false;
  for (size_t i = 0; i < boxes.size(); ++i) {
    float t0 = 0.0f, t1 = 1e30f;
    int axis = -1;
    for (int k = 0; k < 3 && t0 <= t1; ++k) {
      if (d[k] == 0.0f) {
        if (o[k] < boxes[i].lo[k] || o[k] > boxes[i].hi[k]) t0 = 2e30f;
        continue;
      }
      const float a = (boxes[i].lo[k] - o[k]) / d[k], b = (boxes[i].hi[k] - o[k]) / d[k];
      const float near = dm::min(a, b);
      if (near > t0) t0 = near, axis = k;
      t1 = dm::min(t1, dm::max(a, b));
    }
    if (axis < 0 || t0 > t1 || !(t0 < t_hit)) continue;
    hit = true;
    which = i;
    t_hit = t0;
    normal = vec3(0.0f);
    normal[axis] = d[axis] > 0.0f ? -1.0f : 1.0f;
  }
  return hit;
}

}  // namespace

ReflectionProbe render_probe(const vec3& centre, const std::vector<HallBox>& boxes,
                             const HallLight& light) {
  ReflectionProbe p;
  p.centre = centre;
  p.texels.resize(size_t(PROBE_SIZE) * PROBE_SIZE * 6 * 4);
  const HallLight seen_from{centre, light.occluders};
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < PROBE_SIZE; ++y)
      for (int x = 0; x < PROBE_SIZE; ++x) {
        const float s = (2.0f * float(x) + 1.0f) / float(PROBE_SIZE) - 1.0f;
        const float t = (2.0f * float(y) + 1.0f) / float(PROBE_SIZE) - 1.0f;
        const vec3 dv = cube_face_direction(face, s, t);
        const vec3 d = dv / dm::sqrt(glm::dot(dv, dv));
        size_t i = 0;
        float th;
        vec3 n;
        const vec3 c = hit_boxes(centre, d, boxes, i, th, n)
                           ? hall_radiance(centre + d * th, n, boxes[i].albedo, boxes[i].material,
                                           seen_from, SunMap{})
                           : sky(d);
        float* px =
            &p.texels[((size_t(face) * PROBE_SIZE + size_t(y)) * PROBE_SIZE + size_t(x)) * 4];
        px[0] = c.r, px[1] = c.g, px[2] = c.b, px[3] = 1.0f;
      }
  return p;
}

vec3 sample_probe(const ReflectionProbe& p, const vec3& d) {
  const CubeFaceCoord f = cube_face_of(d);
  const float fx = (f.s * 0.5f + 0.5f) * float(PROBE_SIZE) - 0.5f;
  const float fy = (f.t * 0.5f + 0.5f) * float(PROBE_SIZE) - 0.5f;
  const float x0 = dm::floor(fx), y0 = dm::floor(fy);
  const float wx = fx - x0, wy = fy - y0;
  auto texel = [&](float x, float y) {
    const int xi = int(dm::clamp(x, 0.0f, float(PROBE_SIZE - 1)));
    const int yi = int(dm::clamp(y, 0.0f, float(PROBE_SIZE - 1)));
    const float* px =
        &p.texels[((size_t(f.face) * PROBE_SIZE + size_t(yi)) * PROBE_SIZE + size_t(xi)) * 4];
    return vec3(px[0], px[1], px[2]);
  };
  const vec3 top = dm::mix(texel(x0, y0), texel(x0 + 1.0f, y0), wx);
  const vec3 bottom = dm::mix(texel(x0, y0 + 1.0f), texel(x0 + 1.0f, y0 + 1.0f), wx);
  return dm::mix(top, bottom, wy);
}

ShaderTexture probe_texture(const ReflectionProbe& p) {
  return ShaderTexture{"u_probe", PROBE_SIZE, PROBE_SIZE * 6, 4, p.texels};
}

}  // namespace sdfreel::museum
