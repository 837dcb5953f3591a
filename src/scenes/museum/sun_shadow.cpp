#include "scenes/museum/sun_shadow.h"

#include <algorithm>

#include "render/unit_cube.h"
#include "scenes/museum/lighting.h"
#include "scenes/museum/meshes.h"
#include "sdf/det_math.h"

namespace sdfreel::museum {
namespace {

using glm::dvec3;
using glm::vec3;

// The filter: the lit share of a box BOX_TEXELS wide around the point. 5 texels (2.5 cm) is about
// the penumbra of the sun (0.53 degrees across) behind an edge 2.7 m away, the window's distance
// from the plinths by it.
constexpr int BOX_TEXELS = 5;
constexpr int BOX_TAPS = BOX_TEXELS + 1;
static_assert(BOX_TAPS == SUN_MAP_FILTER_TAPS);
constexpr int MARGIN_TEXELS = 4;     // the filter reaches three texels out; one more for rounding
constexpr float BIAS_TEXELS = 1.0f;  // constant depth bias, in texel widths along the beam
// Slope-scaled: a surface at angle theta to the beam moves tan(theta) texels along it per texel
// across, and the filter's taps lie up to 3 texels (4.2 diagonally, with little weight) away.
constexpr float SLOPE_TEXELS = 3.0f;
constexpr float MAX_SLOPE = 8.0f;  // grazing surfaces: the sun is all but gone there anyway

SunView fit_sun_view() {
  const dvec3 f = -glm::normalize(dvec3(TO_SUN));
  const dvec3 r = glm::normalize(glm::cross(f, dvec3(0.0, 1.0, 0.0)));
  const dvec3 u = glm::cross(r, f);
  const dvec3 o(-ROOM_X - 0.5 * WALL, 0.5 * (WINDOW_Y0 + WINDOW_Y1), 0.5 * (WINDOW_Z0 + WINDOW_Z1));
  // Across the beam: the window's opening on both faces of the wall.
  double lo_u = 1e30, hi_u = -1e30, lo_v = 1e30, hi_v = -1e30;
  for (const double x : {-ROOM_X - WALL, -ROOM_X})
    for (const double y : {WINDOW_Y0, WINDOW_Y1})
      for (const double z : {WINDOW_Z0, WINDOW_Z1}) {
        const dvec3 d = dvec3(x, y, z) - o;
        lo_u = std::min(lo_u, glm::dot(d, r)), hi_u = std::max(hi_u, glm::dot(d, r));
        lo_v = std::min(lo_v, glm::dot(d, u)), hi_v = std::max(hi_v, glm::dot(d, u));
      }
  // Along it: the whole hall with its walls.
  double lo_w = 1e30, hi_w = -1e30;
  for (const double x : {-ROOM_X - WALL, ROOM_X + WALL})
    for (const double y : {-WALL, ROOM_H + WALL})
      for (const double z : {-ROOM_Z - WALL, ROOM_Z + WALL}) {
        const double w = glm::dot(dvec3(x, y, z) - o, f);
        lo_w = std::min(lo_w, w), hi_w = std::max(hi_w, w);
      }
  const double texel = std::max(hi_u - lo_u, hi_v - lo_v) / (SUN_MAP_SIZE - 2 * MARGIN_TEXELS);
  const double half = 0.5 * SUN_MAP_SIZE * texel;
  const double n = lo_w - 0.1, fa = hi_w + 0.1;
  SunView s;
  s.origin = vec3(o), s.right = vec3(r), s.up = vec3(u), s.forward = vec3(f);
  s.u0 = float(0.5 * (lo_u + hi_u) - half);
  s.v0 = float(0.5 * (lo_v + hi_v) - half);
  s.texel = float(texel), s.inv_texel = float(1.0 / texel);
  s.near_plane = float(n), s.far_plane = float(fa), s.inv_depth_range = float(1.0 / (fa - n));
  s.size = SUN_MAP_SIZE;
  return s;
}

}  // namespace

const SunView& sun_view() {
  static const SunView view = fit_sun_view();
  return view;
}

PassView sun_pass_view(const SunView& s) {
  const dvec3 r(s.right), u(s.up), f(s.forward), o(s.origin);
  glm::dmat4 view(1.0);
  for (int c = 0; c < 3; ++c) {  // rows right, up, -forward, as camera_model.h
    view[c][0] = r[c];
    view[c][1] = u[c];
    view[c][2] = -f[c];
  }
  view[3] = glm::dvec4(-glm::dot(r, o), -glm::dot(u, o), glm::dot(f, o), 1.0);
  // Orthographic: u in [u0, u0 + size * texel] -> [-1, 1], likewise v; view z = -w, w in
  // [near, far] -> NDC z in [-1, 1], so window depth is (w - near) / (far - near).
  const double extent = double(s.size) * double(s.texel), n = s.near_plane, fa = s.far_plane;
  glm::dmat4 proj(1.0);
  proj[0][0] = 2.0 / extent;
  proj[1][1] = 2.0 / extent;
  proj[2][2] = -2.0 / (fa - n);
  proj[3][0] = -2.0 * double(s.u0) / extent - 1.0;
  proj[3][1] = -2.0 * double(s.v0) / extent - 1.0;
  proj[3][2] = -(fa + n) / (fa - n);
  return PassView{glm::mat4(view), glm::mat4(proj)};
}

float sun_map_depth(const SunView& s, float w) {
  return (w - s.near_plane) * s.inv_depth_range;
}

TargetSpec sun_map_target() {
  TargetSpec t;
  t.name = SUN_MAP_TARGET;
  t.kind = TargetKind::Depth;
  t.size = glm::ivec2(SUN_MAP_SIZE);
  t.per_frame = true;
  return t;
}

MeshPass sun_casters_pass() {
  MeshPass p;
  p.name = "sun shadow map: hall";
  p.mesh = unit_cube();
  p.instances.clear();
  for (const HallBox& b : sun_casters())
    p.instances.push_back(box_instance(b.lo, b.hi, glm::vec4(0.0f)));
  p.colour = "";
  p.depth = SUN_MAP_TARGET;
  p.cull = CullMode::None;  // closed boxes: either side gives the same nearest depth
  p.fragment = "museum/depth_only.frag";
  p.view = sun_pass_view(sun_view());
  return p;
}

// The weights of the BOX_TAPS texels k0 .. k0 + BOX_TEXELS under a box BOX_TEXELS wide centred
// at t (texel k spans [k, k + 1)): the end texels partly, 1 - f and f, the others wholly.
void box_weights(float t, int& k0, float w[BOX_TAPS]) {
  const float left = t - 0.5f * float(BOX_TEXELS);
  const float k = dm::floor(left);
  const float f = left - k;
  k0 = int(k);
  for (int i = 1; i < BOX_TEXELS; ++i) w[i] = 1.0f;
  w[0] = 1.0f - f, w[BOX_TEXELS] = f;
}

float sun_map_visibility(const ImageRGBA& map, const SunView& s, const vec3& p, float ndl,
                         const SunMapWindows* windows) {
  const vec3 d = p - s.origin;
  // Far outside the map every tap is: behind the wall.
  const float far = float(BOX_TEXELS);
  const float tx =
      dm::clamp((glm::dot(d, s.right) - s.u0) * s.inv_texel, -far, float(s.size) + far);
  const float ty = dm::clamp((glm::dot(d, s.up) - s.v0) * s.inv_texel, -far, float(s.size) + far);
  int x0, y0;
  float wx[BOX_TAPS], wy[BOX_TAPS];
  box_weights(tx, x0, wx);
  box_weights(ty, y0, wy);
  // Every tap outside the map (behind the wall): the loop below counts none lit, its 0.
  if (x0 + BOX_TEXELS < 0 || y0 + BOX_TEXELS < 0 || x0 >= s.size || y0 >= s.size) return 0.0f;
  const float slope = dm::min(dm::sqrt(dm::max(1.0f - ndl * ndl, 0.0f)) / ndl, MAX_SLOPE);
  const float bias = (BIAS_TEXELS + SLOPE_TEXELS * slope) * (s.texel * s.inv_depth_range);
  const float ref = sun_map_depth(s, glm::dot(d, s.forward)) - bias;
  // Every tap inside the map and of weight > 0 somewhere (the box's middle taps weigh 1): at most
  // the window's least depth, all pass (the loop's 1); above its greatest, none (its 0).
  const int starts = s.size - BOX_TAPS + 1;
  if (windows && windows->size == s.size && x0 >= 0 && y0 >= 0 && x0 < starts && y0 < starts) {
    const size_t k = size_t(y0) * size_t(starts) + size_t(x0);
    if (ref <= windows->lo[k]) return 1.0f;
    if (ref > windows->hi[k]) return 0.0f;
  }
  float lit = 0.0f;
  int taps = 0, lit_taps = 0;  // of weight above 0: all lit is exactly 1, none exactly 0
  for (int j = 0; j < BOX_TAPS; ++j) {
    float row = 0.0f;
    for (int i = 0; i < BOX_TAPS; ++i) {
      if (!(wx[i] * wy[j] > 0.0f)) continue;
      ++taps;
      const int x = x0 + i, y = y0 + j;
      if (x < 0 || y < 0 || x >= s.size || y >= s.size) continue;  // behind the wall
      if (ref <= map.at(x, s.size - 1 - y)[0]) row = row + wx[i], ++lit_taps;
    }
    lit = lit + row * wy[j];
  }
  if (lit_taps == taps) return 1.0f;
  return lit_taps == 0 ? 0.0f : lit * (1.0f / float(BOX_TEXELS * BOX_TEXELS));
}

std::vector<ShaderUniform> sun_view_uniforms(const SunView& s) {
  return {{"u_sun_origin", 3, {s.origin.x, s.origin.y, s.origin.z}},
          {"u_sun_right", 3, {s.right.x, s.right.y, s.right.z}},
          {"u_sun_up", 3, {s.up.x, s.up.y, s.up.z}},
          {"u_sun_forward", 3, {s.forward.x, s.forward.y, s.forward.z}},
          {"u_sun_map", 4, {s.u0, s.v0, s.inv_texel, float(s.size)}},
          {"u_sun_depth", 3, {s.near_plane, s.inv_depth_range, s.texel * s.inv_depth_range}}};
}

}  // namespace sdfreel::museum
