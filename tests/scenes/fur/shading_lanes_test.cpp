// The fur's fragments in lanes (scenes/fur/shading_lanes.h) against the one-fragment functions,
// bit for bit: random fragments across strand cells (negative UVs included), shells from the
// innermost to the tip, the picture and the hit-id and surface modes, the case with its bodies'
// shadows; and the strand hash in lanes against the scalar hash.
#include "scenes/fur/shading_lanes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "render/quality.h"
#include "scenes/fur/strand_hash.h"

namespace sdfreel::fur {
namespace {

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

MeshFragments8 random_fragments(std::mt19937& rng, const glm::vec4& instance_data) {
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  MeshFragments8 f{};
  for (int k = 0; k < LANES; ++k) {
    f.world_position.set_lane(k, glm::vec3(u(rng), u(rng) + 1.0f, u(rng)));
    f.world_normal.set_lane(k, glm::vec3(u(rng), u(rng), u(rng)));
    f.uv.x[k] = u(rng);
    f.uv.y[k] = u(rng);
  }
  f.instance_data = instance_data;
  f.front_facing = true;
  return f;
}

template <class Lanes, class One>
int mismatches(const MeshFragments8& f, Lanes lanes, One one) {
  FragmentColours8 c{};
  lanes(f, c);
  int bad = 0;
  for (int k = 0; k < LANES; ++k) {
    MeshFragment s;
    s.world_position = f.world_position.lane(k);
    s.world_normal = f.world_normal.lane(k);
    s.uv = glm::vec2(f.uv.x[k], f.uv.y[k]);
    s.instance_data = f.instance_data;
    s.front_facing = f.front_facing;
    const glm::vec4 want = one(s);
    const float got[4] = {c.r[k], c.g[k], c.b[k], c.a[k]};
    for (int i = 0; i < 4; ++i) bad += !same_bits(got[i], want[i]);
  }
  return bad;
}

ShellLook shell_look() {
  ShellLook l;
  l.density = 80.0f, l.thickness = 2.2f;
  l.base = glm::vec3(0.3f, 0.2f, 0.1f), l.tip = glm::vec3(0.9f, 0.8f, 0.6f);
  l.light_dir = glm::normalize(glm::vec3(-0.35f, 0.85f, -0.45f));
  l.light = glm::vec3(1.0f, 0.95f, 0.88f), l.ambient = glm::vec3(0.16f, 0.17f, 0.2f);
  l.eye = glm::vec3(0.2f, 1.5f, 3.0f);
  return l;
}

TEST(FurShadingLanes, ShellsHaveTheBitsOfOneFragment) {
  std::mt19937 rng(3);
  int bad = 0, gaps = 0, kept = 0;
  for (int mode = 0; mode < 4; ++mode) {
    ShellLook look = shell_look();
    if (mode == 1) look.hit_id = 3.0f;
    if (mode == 2) look.surface = SURFACE_DISTANCE;
    if (mode == 3) look.surface = SURFACE_NORMAL;
    for (int rep = 0; rep < 3000; ++rep) {
      const int n = 32, i = rep % n;
      const MeshFragments8 f = random_fragments(rng, shell_data(i, n, 1.0f));
      bad += mismatches(
          f, [&](const MeshFragments8& x, FragmentColours8& c) { shade_shell8(look, x, c); },
          [&](const MeshFragment& x) { return shade_shell(look, x); });
      FragmentColours8 c{};
      shade_shell8(look, f, c);
      for (int k = 0; k < LANES; ++k) (c.a[k] > 0.0f ? kept : gaps) += 1;
    }
  }
  EXPECT_EQ(bad, 0);
  EXPECT_GT(gaps, 1000);  // both sides of the strand test were exercised
  EXPECT_GT(kept, 1000);
}

TEST(FurShadingLanes, CaseHasTheBitsOfOneFragment) {
  std::mt19937 rng(4);
  int bad = 0;
  for (int mode = 0; mode < 3; ++mode) {
    CaseLook look;
    look.light_dir = glm::normalize(glm::vec3(-0.35f, 0.85f, -0.45f));
    look.light = glm::vec3(1.2f, 1.1f, 1.0f), look.ambient = glm::vec3(0.16f, 0.17f, 0.2f);
    for (size_t b = 0; b < look.bodies.size(); ++b)
      look.bodies[b] = glm::vec4(-0.5f + 0.5f * float(b), 0.2f, 0.1f * float(b), 0.3f);
    look.hit_mask = mode == 1;
    if (mode == 2) look.surface = SURFACE_NORMAL;
    for (int rep = 0; rep < 3000; ++rep)
      bad += mismatches(
          random_fragments(rng, glm::vec4(0.42f, 0.4f, 0.37f, 0.0f)),
          [&](const MeshFragments8& x, FragmentColours8& c) { shade_case8(look, x, c); },
          [&](const MeshFragment& x) { return shade_case(look, x); });
  }
  EXPECT_EQ(bad, 0);
}

TEST(FurShadingLanes, StrandHashInLanes) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(-100000, 100000);
  int bad = 0;
  for (int rep = 0; rep < 5000; ++rep) {
    M8 x{}, y{};
    for (int k = 0; k < LANES; ++k) x[k] = cell(rng), y[k] = cell(rng);
    const F8 r = strand_random(x, y);
    for (int k = 0; k < LANES; ++k) bad += !same_bits(r[k], strand_random(int(x[k]), int(y[k])));
  }
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace sdfreel::fur
