// The reference and naive marches and the cell walk in eight lanes (march_lanes, marchNaive_lanes,
// marchCells_lanes) give, lane by lane, the scalar marches' hits, bits and RayStats: random rays
// over the lanterns, rays straight down the lanterns' axes, level rays (the slab clip's flat
// branch), over-relaxed and plain steps, and a small step budget (the capped count), with lanes
// switched off; the cell walk also with a cell table too small for the rays, whose cells outside it
// are computed on demand.
#include "scenes/lantern_festival/march_lanes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "scenes/lantern_festival/lanes_context.h"
#include "scenes/lantern_festival/scene.h"
#include "scenes/registry.h"

namespace sdfreel::lantern_festival {
namespace {

struct RayLanes {
  V3x8 o, dir;
  F8 t_offset;
  M8 active;
};

// Packets of rays from above the lake over a few cells; every fourth lane looks straight down a
// lantern's axis and every seventh packet is level.
std::vector<RayLanes> random_rays(float size, int packets) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> across(-3.0f * size, 3.0f * size), height(0.2f, 6.0f),
      unit(-1.0f, 1.0f), offset(0.0f, 20.0f);
  std::uniform_int_distribution<int> cell(-3, 3);
  std::vector<RayLanes> out;
  for (int k = 0; k < packets; ++k) {
    alignas(32) float ox[LANES], oy[LANES], oz[LANES], dx[LANES], dy[LANES], dz[LANES];
    RayLanes r{};
    for (int i = 0; i < LANES; ++i) {
      glm::vec3 o(across(rng), height(rng), across(rng));
      glm::vec3 d(unit(rng), -0.2f - 0.8f * std::abs(unit(rng)), unit(rng));
      if (i % 4 == 1) {
        o = glm::vec3(float(cell(rng)) * size, height(rng), float(cell(rng)) * size);
        d = glm::vec3(0.0f, -1.0f, 0.0f);
      }
      if (k % 7 == 3) d = glm::vec3(d.x + 0.1f, 0.0f, d.z);  // level, never zero
      d = glm::normalize(d);
      ox[i] = o.x, oy[i] = o.y, oz[i] = o.z, dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
      r.t_offset[i] = offset(rng);
      r.active[i] = (k % 3 == 2 && i == 5) ? 0 : -1;  // some packets with a lane off
    }
    r.o = V3x8(load8(ox), load8(oy), load8(oz));
    r.dir = V3x8(load8(dx), load8(dy), load8(dz));
    out.push_back(r);
  }
  return out;
}

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_stats(const RayStats& a, const RayStats& b) {
  return a.sdf_evals == b.sdf_evals && a.steps == b.steps && a.capped == b.capped;
}

class LanternFestivalMarchLanes : public ::testing::Test {
 protected:
  void SetUp() override { scene_.prepare(test::lantern_lanes_context(3.7)); }
  LanternFestivalScene scene_;
};

TEST_F(LanternFestivalMarchLanes, ReferenceMarchGivesScalarBitsAndStats) {
  const LanternField& f = scene_.field();
  const std::vector<RayLanes> rays = random_rays(f.grid.size, 96);
  int mismatches = 0, hits = 0, capped = 0;
  for (int max_steps : {256, 12})
    for (float step_factor : {1.0f, 1.6f}) {
      const MarchLimits lim{max_steps, 0.25f, step_factor, 1e-3f, 0.0f};
      for (const RayLanes& r : rays) {
        const F8 t_max = splat(60.0f);
        RayStats lanes, scalar;
        const MarchHitLanes h =
            march_lanes(f, r.o, r.dir, splat(0.0f), t_max, lim, r.t_offset, r.active, lanes);
        for (int i = 0; i < LANES; ++i) {
          if (!lane(r.active, i)) continue;
          MarchLimits li = lim;
          li.t_offset = r.t_offset[i];
          const MarchHit want = march(f, r.o.lane(i), r.dir.lane(i), 0.0f, t_max[i], li, scalar);
          hits += want.hit;
          if (want.hit != lane(h.hit, i) || (want.hit && !same_bits(want.t, h.t[i]))) ++mismatches;
        }
        capped += int(scalar.capped);
        EXPECT_TRUE(same_stats(lanes, scalar)) << "max_steps " << max_steps;
      }
    }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(hits, 100);  // the rays do meet lanterns, and some run out of steps
  EXPECT_GT(capped, 0);
}

TEST_F(LanternFestivalMarchLanes, CellWalkGivesScalarBitsAndStatsInAndOutsideTheTable) {
  LanternField small = scene_.field();
  small.table.build(small.grid, small.lake, glm::vec2(0.0f), 1);  // 3 x 3 cells; rays span 7 x 7
  const std::vector<RayLanes> rays = random_rays(small.grid.size, 96);
  int mismatches = 0, hits = 0, hits_off_table = 0, capped = 0;
  const LanternField* whole = &scene_.field();
  for (const LanternField* f : {whole, static_cast<const LanternField*>(&small)})
    for (int max_steps : {256, 12}) {
      const MarchLimits lim{max_steps, 0.25f, 1.2f, 1e-3f, 0.0f};
      for (const RayLanes& r : rays) {
        const F8 t_max = splat(60.0f);
        RayStats lanes, scalar;
        const CellHitLanes h =
            marchCells_lanes(*f, r.o, r.dir, splat(0.0f), t_max, lim, r.t_offset, r.active, lanes);
        for (int i = 0; i < LANES; ++i) {
          if (!lane(r.active, i)) continue;
          MarchLimits li = lim;
          li.t_offset = r.t_offset[i];
          const CellHit want =
              marchCells(*f, r.o.lane(i), r.dir.lane(i), 0.0f, t_max[i], li, scalar);
          hits += want.hit;
          const glm::vec3 c = want.cell.center;
          if (f == &small && want.hit &&
              std::max(std::abs(c.x), std::abs(c.z)) > 1.5f * f->grid.size)
            ++hits_off_table;
          const bool same =
              want.hit == lane(h.hit, i) &&
              (!want.hit || (same_bits(want.t, h.t[i]) &&
                             std::memcmp(&want.cell, &h.cell[i], sizeof want.cell) == 0));
          mismatches += !same;
        }
        capped += int(scalar.capped);
        EXPECT_TRUE(same_stats(lanes, scalar)) << "max_steps " << max_steps;
      }
    }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(hits, 100);
  EXPECT_GT(hits_off_table, 20);  // lanterns whose cells the small table does not hold
  EXPECT_GT(capped, 0);
}

TEST_F(LanternFestivalMarchLanes, NaiveMarchGivesScalarBitsAndStats) {
  const LanternField& f = scene_.field();
  const std::vector<RayLanes> rays = random_rays(f.grid.size, 96);
  int mismatches = 0, water = 0, lanterns = 0, capped = 0;
  for (bool with_water : {true, false})
    for (int max_steps : {256, 12}) {
      MarchLimits lim{max_steps, 1e-3f, 1.0f, 1e-3f, 0.0f};
      lim.naive = true;
      for (const RayLanes& r : rays) {
        RayStats lanes, scalar;
        const NaiveHitLanes h = marchNaive_lanes(f, r.o, r.dir, splat(60.0f), with_water, lim,
                                                 r.t_offset, r.active, lanes);
        for (int i = 0; i < LANES; ++i) {
          if (!lane(r.active, i)) continue;
          const NaiveHit want =
              marchNaive(f, r.o.lane(i), r.dir.lane(i), 60.0f, with_water, lim, scalar);
          water += want.hit && want.water;
          lanterns += want.hit && !want.water;
          const bool same =
              want.hit == lane(h.hit, i) &&
              (!want.hit || (want.water == lane(h.water, i) && same_bits(want.t, h.t[i]) &&
                             want.cell.center == h.cell[i].center));
          mismatches += !same;
        }
        capped += int(scalar.capped);
        EXPECT_TRUE(same_stats(lanes, scalar)) << "max_steps " << max_steps;
      }
    }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(water, 100);
  EXPECT_GT(lanterns, 100);
  EXPECT_GT(capped, 0);
}

}  // namespace
}  // namespace sdfreel::lantern_festival
