// The irregular lantern grid: repeated() is continuous across cell borders and centre lines,
// never claims more room than the true nearest lantern leaves, and the fast cell-walking marcher
// finds the same hits as sphere tracing repeated().
#include "scenes/lantern_festival/grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "scenes/lantern_festival/generated_textures.h"
#include "scenes/lantern_festival/march.h"
#include "sdf/noise.h"

namespace sdfreel::lantern_festival {
namespace {

struct Fixture {
  Texture blue_noise = make_blue_noise(BLUE_NOISE_SIZE, 4, 1u);
  LanternField field;
  Fixture(double time = 3.0, float spacing = 8.0f, float jitter = 1.0f, float scale = 1.0f) {
    field.lake = make_lake_frame(time, 0.15f, 2.5f);
    field.grid = make_grid_frame(field.lake, spacing, jitter, scale, blue_noise);
    field.table.build(field.grid, field.lake, glm::vec2(0.0f), 6);
  }
};

// Ground truth: every lantern of a 5 x 5 block of cells, exact distances.
float brute_force(const LanternField& f, const glm::vec3& p) {
  const glm::vec2 id = cellId(f.grid, glm::vec2(p.x, p.z));
  float d = 1e20f;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)
      d = std::min(
          d, lanternDistance(f.grid, lanternCellAt(f.grid, f.lake, id + glm::vec2(i, j)), p, true));
  return d;
}

float unit(uint32_t& state) {
  state = pcg_hash(state);
  return hash_to_unit(state);
}

TEST(LanternFestivalGrid, LanternsStayInsideTheirCell) {
  const Fixture fx;
  const GridFrame& g = fx.field.grid;
  EXPECT_LE(g.extent, 0.5f * g.size + 1e-5f);
  for (int j = -20; j <= 20; ++j)
    for (int i = -20; i <= 20; ++i) {
      const glm::vec2 id(i, j);
      const LanternCell c = lanternCellAt(g, fx.field.lake, id);
      const glm::vec2 off = glm::vec2(c.center.x, c.center.z) - id * g.size;
      EXPECT_LE(std::max(std::fabs(off.x), std::fabs(off.y)) + g.bound_radius,
                0.5f * g.size + 1e-4f);
    }
}

TEST(LanternFestivalGrid, TableMatchesOnDemandCells) {
  const Fixture fx;
  for (int j = -9; j <= 9; ++j)  // inside and outside the table's window
    for (int i = -9; i <= 9; ++i) {
      const LanternCell a = fx.field.cell(glm::vec2(i, j));
      const LanternCell b = lanternCellAt(fx.field.grid, fx.field.lake, glm::vec2(i, j));
      EXPECT_EQ(a.center, b.center);
      EXPECT_EQ(a.to_local[0], b.to_local[0]);
      EXPECT_EQ(a.flicker_phase, b.flicker_phase);
    }
}

TEST(LanternFestivalGrid, NeverFartherThanTheNearestLantern) {
  for (const Fixture& fx :
       {Fixture(3.0), Fixture(17.5, 3.0f, 1.0f, 1.0f), Fixture(0.0, 8.0f, 0.3f, 1.7f)}) {
    uint32_t s = 11u;
    const GridFrame& g = fx.field.grid;
    for (int k = 0; k < 20000; ++k) {
      const glm::vec3 p((unit(s) - 0.5f) * 6.0f * g.size,
                        g.slab_lo + unit(s) * (g.slab_hi - g.slab_lo),
                        (unit(s) - 0.5f) * 6.0f * g.size);
      const float truth = brute_force(fx.field, p);
      // A lower bound of the true distance everywhere (no lantern missed or cut) ...
      ASSERT_LE(repeated(fx.field, p, true), truth + 1e-5f) << p.x << " " << p.y << " " << p.z;
      ASSERT_LE(repeated(fx.field, p, false), truth + 1e-5f);
      // ... and the exact distance near the lanterns, where it matters for hits and normals.
      if (truth < 0.5f * g.scale) {
        ASSERT_NEAR(repeated(fx.field, p, true), truth, 1e-5f);
      }
    }
  }
}

// Walk lines across many cells in x and in z, including lines exactly on cell centre lines
// (where the neighbour direction is sign(0)) and on borders: consecutive samples may differ by
// at most the sampling step (the field is 1-Lipschitz, so it has no jumps).
TEST(LanternFestivalGrid, ContinuousAcrossCellBorders) {
  const Fixture fx;
  const GridFrame& g = fx.field.grid;
  const float step = 0.01f;
  const float offsets[] = {0.0f, 0.5f * g.size, 0.37f * g.size, 1.0f * g.size, -2.0f * g.size};
  const float heights[] = {g.slab_lo + 0.3f, -0.5f, 0.0f, 0.6f};
  int lines = 0, border_crossings = 0;
  for (int axis = 0; axis < 2; ++axis)
    for (float off : offsets)
      for (float y : heights) {
        float prev = 0.0f;
        glm::vec2 prev_id(0.0f);
        for (int i = 0; i <= int(4.0f * g.size / step); ++i) {
          const float s = -2.0f * g.size + float(i) * step;
          const glm::vec3 p = axis == 0 ? glm::vec3(s, y, off) : glm::vec3(off, y, s);
          const float d = repeated(fx.field, p, true);
          const glm::vec2 id = cellId(g, glm::vec2(p.x, p.z));
          if (i > 0) {
            ASSERT_LE(std::fabs(d - prev), step * 1.001f + 1e-5f) << "axis " << axis << " at " << s;
            border_crossings += id != prev_id;
          }
          prev = d;
          prev_id = id;
        }
        ++lines;
      }
  EXPECT_EQ(lines, 40);
  EXPECT_GE(border_crossings, lines * 4);
}

TEST(LanternFestivalGrid, CentreLinesUseTwoDistinctNeighbours) {
  const Fixture fx;
  const GridFrame& g = fx.field.grid;
  // Points exactly on cell centre lines (p - size * id == 0 in x, z or both).
  for (int j = -3; j <= 3; ++j)
    for (int i = -3; i <= 3; ++i)
      for (float y : {-0.8f, 0.2f}) {
        const float x = float(i) * g.size, z = float(j) * g.size;
        for (const glm::vec3& p : {glm::vec3(x, y, z), glm::vec3(x, y, z + 0.3f * g.size),
                                   glm::vec3(x - 0.45f * g.size, y, z)}) {
          EXPECT_LE(repeated(fx.field, p, true), brute_force(fx.field, p) + 1e-5f);
        }
      }
  EXPECT_EQ(neighbourSign(0.0f), 1.0f);
  EXPECT_EQ(neighbourSign(-0.0f), 1.0f);
  EXPECT_EQ(neighbourSign(-1e-30f), -1.0f);
}

// A hand-made blue-noise texture that pushes lanterns where the plain 2 x 2 rule fails: every
// lantern sits on its cell centre except the ones set here (bn 0 or 1 = the largest offset).
struct AdversarialFixture {
  Texture blue_noise{BLUE_NOISE_SIZE, BLUE_NOISE_SIZE, 4};
  LanternField field;
  void put(int i, int j, float bx, float bz) {
    float* t = blue_noise.at((i + BLUE_NOISE_SIZE) % BLUE_NOISE_SIZE,
                             (j + BLUE_NOISE_SIZE) % BLUE_NOISE_SIZE);
    t[0] = bx;
    t[1] = bz;
  }
  AdversarialFixture() {
    std::fill(blue_noise.texels.begin(), blue_noise.texels.end(), 0.5f);
    // Centre = id * size - (bn * 2 - 1) * max_offset: bn 1 moves to -x/-z, bn 0 to +x/+z.
    put(0, 0, 1.0f, 1.0f);   // own lantern to the far (-x, -z) corner
    put(1, 0, 0.0f, 0.0f);   // x neighbour far away (+x, +z)
    put(0, 1, 1.0f, 0.0f);   // z neighbour far away (-x, +z)
    put(1, 1, 0.0f, 0.0f);   // diagonal neighbour far away
    put(0, -1, 0.0f, 0.0f);  // unchecked cell behind: its lantern right at the shared corner
    field.lake = make_lake_frame(0.0, 0.0f, 0.0f);  // flat water: lanterns upright
    field.grid = make_grid_frame(field.lake, 8.0f, 1.0f, 1.0f, blue_noise);
    field.table.build(field.grid, field.lake, glm::vec2(0.0f), 3);
  }
};

TEST(LanternFestivalGrid, OthersBoundCatchesLanternsTheFourCellsMiss) {
  const AdversarialFixture fx;
  const GridFrame& g = fx.field.grid;
  // Near the (+x, +z) corner of cell (0, 0): the nearest lantern is in cell (0, -1), unchecked.
  const glm::vec3 p(0.5f * g.size - 0.01f, 0.0f, 0.01f);
  const float truth = brute_force(fx.field, p);
  EXPECT_GT(nearestFour(fx.field, p, true), truth + 0.5f);  // the plain rule overestimates ...
  EXPECT_LE(repeated(fx.field, p, true), truth + 1e-5f);    // ... the bound repairs it
  EXPECT_LE(repeated(fx.field, p, false), truth + 1e-5f);
}

TEST(LanternFestivalGrid, CentreLineLooksAtARealNeighbour) {
  AdversarialFixture fx;
  // Own lantern pushed to -z, the +z neighbour pushed further, the +x neighbour close: on the
  // centre line x = 0 only a distinct x neighbour (sign(0) != 0) sees the nearest lantern.
  fx.put(0, 0, 0.5f, 1.0f);
  fx.put(0, 1, 0.5f, 0.0f);
  fx.put(1, 0, 1.0f, 0.0f);
  fx.put(-1, 0, 0.0f, 1.0f);
  fx.field.table.build(fx.field.grid, fx.field.lake, glm::vec2(0.0f), 3);
  const GridFrame& g = fx.field.grid;
  const glm::vec3 p(0.0f, 0.0f, 0.45f * g.size);
  const float truth = brute_force(fx.field, p);
  // The configuration really is the hard one: the nearest lantern is the +x neighbour's.
  EXPECT_NEAR(lanternDistance(g, fx.field.cell(glm::vec2(1.0f, 0.0f)), p, true), truth, 1e-5f);
  EXPECT_GT(lanternDistance(g, fx.field.cell(glm::vec2(0.0f)), p, true), truth + 0.1f);
  EXPECT_NEAR(nearestFour(fx.field, p, true), truth, 1e-5f);
}

TEST(LanternFestivalGrid, CellWalkFindsTheSameHitsAsSphereTracing) {
  const Fixture fx;
  MarchLimits lim;
  lim.max_steps = 2048;
  lim.hit_eps = 0.05f;
  lim.step_factor = 1.2f;
  lim.pixel_angle = 1e-3f;
  uint32_t s = 5u;
  int hits = 0, agree = 0, total = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::vec3 o((unit(s) - 0.5f) * 40.0f, 0.2f + unit(s) * 2.0f, (unit(s) - 0.5f) * 40.0f);
    const float az = unit(s) * dm::TWO_PI, el = -0.3f + unit(s) * 0.4f;
    const glm::vec3 dir = glm::normalize(
        glm::vec3(std::cos(az) * std::cos(el), std::sin(el), std::sin(az) * std::cos(el)));
    RayStats st;
    const MarchHit a = march(fx.field, o, dir, 0.0f, 80.0f, lim, st);
    const CellHit b = marchCells(fx.field, o, dir, 0.0f, 80.0f, lim, st);
    ++total;
    hits += a.hit;
    if (a.hit == b.hit && (!a.hit || std::fabs(a.t - b.t) < 0.02f)) ++agree;
  }
  EXPECT_GT(hits, total / 10);  // the fan really hits lanterns
  EXPECT_GE(agree, total - total / 200) << agree << " of " << total;
}

TEST(LanternFestivalGrid, BoundIntervalContainsTheLantern) {
  const Fixture fx;
  const GridFrame& g = fx.field.grid;
  const LanternCell c = fx.field.cell(glm::vec2(0.0f));
  uint32_t s = 3u;
  for (int k = 0; k < 2000; ++k) {
    const glm::vec3 o =
        c.center + glm::vec3((unit(s) - 0.5f) * 10.0f, (unit(s) - 0.5f) * 6.0f, -6.0f);
    const glm::vec3 target =
        c.center + glm::vec3((unit(s) - 0.5f) * 2.0f, (unit(s) - 0.5f) * 2.4f, 0.0f);
    const glm::vec3 dir = glm::normalize(target - o);
    float t0 = 0.0f, t1 = 0.0f;
    const bool inside = boundInterval(g, c.center, o, dir, t0, t1);
    // Any point of the ray on or in the lantern lies within the interval.
    for (float t = 0.0f; t < 14.0f; t += 0.005f)
      if (lanternDistance(g, c, o + dir * t, true) <= 0.0f) {
        ASSERT_TRUE(inside);
        ASSERT_GE(t, t0 - 1e-3f);
        ASSERT_LE(t, t1 + 1e-3f);
      }
  }
}

}  // namespace
}  // namespace sdfreel::lantern_festival
