#pragma once
// Water droplets on the pads and the petals (seed 001's wish list: "add water droplets"). A drop
// is a small dome of water placed by a hash on a grid over its object's own ground plan (x and z
// from the pad's or the flower's centre), so it stays put as time passes and rides the drifting
// pad; only faces that look up hold one. Each grid cell holds at most one drop, inside the cell
// (one hash per point). GLSL twin: shaders/water_lily/droplets.glsl.
#include <cstdint>
#include <glm/glm.hpp>

#include "sdf/det_math.h"
#include "sdf/noise.h"

namespace sdfreel::water_lily {

constexpr float DROP_CELL = 0.11f;   // grid cell, world units (a flower is about 1.2 across)
constexpr float DROP_MIN_R = 0.12f;  // radius range, in cells: a drop never leaves its cell
constexpr float DROP_MAX_R = 0.26f;
constexpr float DROP_SHARE_PAD = 0.45f;              // share of cells with a drop, on pads ...
constexpr float DROP_SHARE_PETAL = 0.22f;            // ... and on petals
constexpr float DROP_EDGE = 0.12f;                   // the soft edge, in radii
constexpr float DROP_MARGIN = 0.02f;                 // kept clear along the cell's sides, in cells
constexpr float DROP_UP0 = 0.45f, DROP_UP1 = 0.75f;  // faces with n.y below UP0 hold none
constexpr uint32_t DROP_SEED = 907u;
// Their look (render.cpp's addDroplet): the dome's normal tilt at the rim, the dark ring's start
// (in radii) and depth, the caustic's gain, the water's sharp highlight.
constexpr float DROP_SLOPE = 1.4f;
constexpr float DROP_RING = 0.55f, DROP_RING_DARK = 0.6f;
constexpr float DROP_CAUSTIC = 1.6f;
constexpr float DROP_SHININESS = 256.0f, DROP_SPECULAR = 1.5f;

// Where a point of the ground plan stands in its cell's drop, if any.
struct Droplet {
  float cover = 0.0f;      // 0 outside .. 1 inside (a soft edge at the rim)
  glm::vec2 offset{0.0f};  // from the drop's centre, in its radii: |offset| < 1 inside
};

// xz: the point on the object's ground plan; seed: the object's; share: of cells with a drop
// (0: none); up: the face's normal's y.
inline Droplet dropletAt(const glm::vec2& xz, uint32_t seed, float share, float up) {
  Droplet drop;
  const float face = dm::smoothstep(DROP_UP0, DROP_UP1, up);
  if (!(face > 0.0f)) return drop;
  const float fx = dm::floor(xz.x / DROP_CELL), fz = dm::floor(xz.y / DROP_CELL);
  const uint32_t h = hash2i(int32_t(fx), int32_t(fz), seed);
  if (!(hash_to_unit(h) < share)) return drop;
  const uint32_t hx = pcg_hash(h), hz = pcg_hash(hx), hr = pcg_hash(hz);
  const float radius = DROP_MIN_R + (DROP_MAX_R - DROP_MIN_R) * hash_to_unit(hr);
  // The centre keeps the whole drop inside the cell, clear of its sides (no seam between cells).
  const float inset = radius + DROP_MARGIN, span = 1.0f - 2.0f * inset;
  const float cx = fx + inset + span * hash_to_unit(hx);
  const float cz = fz + inset + span * hash_to_unit(hz);
  drop.offset = glm::vec2((xz.x / DROP_CELL - cx) / radius, (xz.y / DROP_CELL - cz) / radius);
  const float d = dm::sqrt(drop.offset.x * drop.offset.x + drop.offset.y * drop.offset.y);
  drop.cover = face * (1.0f - dm::smoothstep(1.0f - DROP_EDGE, 1.0f, d));
  return drop;
}

}  // namespace sdfreel::water_lily
