#pragma once
// The sun's shadow map: the depth of what casts the sun's shadows into the hall (the west wall
// with its window and mullions, the plinths, the bench, exhibit 1) seen from the sun through an
// orthographic projection. Every sunlit point of the room sees the sun through the window, so the
// projection is fitted to the window's opening (plus the filter's margin) rather than to the whole
// hall: all of the map's texels land in the beam, 5 mm each at SUN_MAP_SIZE 512. A point outside
// the map is behind the wall: in shadow.
//
// The map is drawn once a frame by setup passes of the plan (render/frame_plan.h): the casters as
// a depth-only mesh pass with the sun's view (GL rasterises it, the CPU with its own rasteriser
// and GL's coverage rules), exhibit 1 ray-marched from the sun inside its bound (sdf_exhibit.h).
// Shading reads it with a box-filtered percentage-closer filter (the lit share of a box five texels
// wide around the point, about the sun's penumbra by the window, its 6x6 texels weighted by how
// much of each the box covers, so a shadow's edge is a ramp that moves smoothly with the point
// instead of steps of whole texels) and a slope-scaled bias, the same operations in C++ (here) and
// GLSL (shaders/museum/sun_shadow.glsl).
#include <glm/glm.hpp>
#include <vector>

#include "render/frame_plan.h"
#include "render/image.h"
#include "scenes/museum/sun_map_windows.h"

namespace sdfreel::museum {

constexpr int SUN_MAP_SIZE = 512;       // texels a side (docs/scenes/museum.md: measured)
constexpr int SUN_MAP_FILTER_TAPS = 6;  // texels a side the filter reads (a box 5 texels wide)
constexpr const char* SUN_MAP_TARGET = "sun_shadow";
constexpr const char* SUN_MAP_SAMPLER = "u_sun_shadow";

// Light space of the map: u = dot(p - origin, right), v = dot(p - origin, up) across the beam,
// w = dot(p - origin, forward) along it (forward = -TO_SUN). Texel (i, j) covers
// u in u0 + [i, i + 1) * texel, v likewise; window depth is (w - near) / (far - near).
struct SunView {
  glm::vec3 origin, right, up, forward;
  float u0, v0, texel, inv_texel;
  float near_plane, far_plane, inv_depth_range;
  int size;
};

// The view of the hall's layout and TO_SUN (fixed: frames stay pure functions of the timeline).
const SunView& sun_view();
// Its view and orthographic projection for a mesh pass (GL's conventions, NDC z in [-1, 1]).
PassView sun_pass_view(const SunView& s);
// Window depth in the map of a point at w along the sun's direction.
float sun_map_depth(const SunView& s, float w);

// The per-frame depth target of the map.
TargetSpec sun_map_target();
// The depth-only pass of the hall's casters into the map.
MeshPass sun_casters_pass();

// 0..1: the share of the filter's texels that see the sun from p (normal n, ndl =
// dot(n, TO_SUN) > 0), read from `map` (the target SUN_MAP_TARGET, CPU rows top-down). With the
// map's windows (sun_map_windows.h), fully lit and fully shadowed points skip the taps: the same
// result.
float sun_map_visibility(const ImageRGBA& map, const SunView& s, const glm::vec3& p, float ndl,
                         const SunMapWindows* windows = nullptr);

// u_sun_origin, u_sun_right, u_sun_up, u_sun_forward, u_sun_map (u0, v0, inv_texel, size),
// u_sun_depth (near, inv_depth_range, texel * inv_depth_range).
std::vector<ShaderUniform> sun_view_uniforms(const SunView& s);

}  // namespace sdfreel::museum
