#pragma once
// Ray marching for the lantern scene, clipped to the slabs that hold the lanterns and the waves:
// - march(): the seed's way, over-relaxed sphere tracing of repeated() (with the fall-back of
//   Keinert et al. 2014, so a relaxed step never skips a surface). The reference path.
// - marchCells(): the same hits, faster. Every lantern lies inside its own cell, so the ray walks
//   the cells it crosses in order (2D DDA), skips each lantern whose bounding cylinder it misses
//   (one analytic test per cell), and sphere-traces only that lantern inside its cylinder.
// - marchWater(): steps of gap / (the fastest the gap can shrink along the ray), from the lake's
//   Lipschitz bound, so it never overshoots.
// Normals by the tetrahedron technique.
#include <glm/glm.hpp>

#include "scenes/lantern_festival/grid.h"
#include "scenes/lantern_festival/lake.h"
#include "scenes/scene.h"

namespace sdfreel::lantern_festival {

struct MarchLimits {
  int max_steps = 256;
  float hit_eps = 0.25f;     // at unit distance, in pixel footprints
  float step_factor = 1.0f;  // over-relaxation
  float pixel_angle = 1e-3f;
  float t_offset = 0.0f;  // distance already travelled (reflections): the footprint grows with it
  bool naive = false;     // MarchSettings::naive: hit_eps is a fixed world-space threshold
  float eps_at(float t) const { return naive ? hit_eps : hit_eps * (t_offset + t) * pixel_angle; }
};

struct MarchHit {
  bool hit = false;
  float t = 0.0f;
};

// Lanterns along o + t dir for t in [t_min, t_max].
MarchHit march(const LanternField& f, const glm::vec3& o, const glm::vec3& dir, float t_min,
               float t_max, const MarchLimits& lim, RayStats& stats);

struct CellHit {
  bool hit = false;
  float t = 0.0f;
  LanternCell cell{};  // the lantern hit
};
CellHit marchCells(const LanternField& f, const glm::vec3& o, const glm::vec3& dir, float t_min,
                   float t_max, const MarchLimits& lim, RayStats& stats);

// The ray's interval inside a lantern's bounding cylinder (vertical axis through c); false if none.
bool boundInterval(const GridFrame& g, const glm::vec3& c, const glm::vec3& o, const glm::vec3& dir,
                   float& t0, float& t1);

// The naive preset's march: plain sphere tracing (factor 1) of the exact lantern field, and of the
// lake too when `with_water`, over [0, t_max]: no slabs, bounding cylinders or cell walk. The
// lake's vertical gap is stepped as if it were a distance, as the textbook loop does.
struct NaiveHit {
  bool hit = false;
  bool water = false;  // the hit is the lake's (else a lantern's)
  float t = 0.0f;
  LanternCell cell{};  // the lantern hit
};
NaiveHit marchNaive(const LanternField& f, const glm::vec3& o, const glm::vec3& dir, float t_max,
                    bool with_water, const MarchLimits& lim, RayStats& stats);

// The lake along o + t dir for t in [0, t_max].
MarchHit marchWater(const LakeFrame& lake, const glm::vec3& o, const glm::vec3& dir, float t_max,
                    const MarchLimits& lim, RayStats& stats);

// Tetrahedron normals (four taps at the vertices of a tetrahedron of size eps).
extern const glm::vec3 TETRA[4];
glm::vec3 lanternNormal(const GridFrame& g, const LanternCell& c, const glm::vec3& p, float eps);
glm::vec3 waterNormal(const LakeFrame& lake, const glm::vec3& p, float eps);

}  // namespace sdfreel::lantern_festival
