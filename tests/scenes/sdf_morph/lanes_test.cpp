// sdf_morph's geometry is one template for the scalar path and the eight-lane path: every lane
// must give the scalar bits, at every morph stage, near and far from the object's bound, for the
// bounded scene distance (with its `exact` flag) and for the scene's DistanceFunctions.
#include "scenes/sdf_morph/lanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "render/frame_context.h"
#include "scenes/registry.h"
#include "scenes/sdf_morph/environment.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/render.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel::sdf_morph {
namespace {

using glm::vec3;

bool sameBits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

MorphUniforms uniforms(float morph, float angle, bool naive = false) {
  MorphUniforms u;
  u.morph = morph;
  u.rot_cos = std::cos(angle);
  u.rot_sin = std::sin(angle);
  u.naive = naive;
  return u;
}

// Points in a box around object and pedestal (inside, on and beyond the bounding sphere),
// a multiple of LANES.
std::vector<vec3> points(unsigned seed, int n = 8 * 400) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> xz(-1.3f, 1.3f), y(-0.1f, 1.9f);
  std::vector<vec3> out;
  for (int i = 0; i < n; ++i) out.push_back(vec3(xz(rng), y(rng), xz(rng)));
  return out;
}

V3x8 gather(const std::vector<vec3>& p, int base) {
  V3x8 v;
  for (int i = 0; i < LANES; ++i) v.set_lane(i, p[base + i]);
  return v;
}

const float MORPHS[] = {0.0f, 0.2f, 0.5f, 0.85f, 1.0f};

TEST(SdfMorphLanes, ObjectPartsGiveTheScalarBits) {
  for (float morph : MORPHS) {
    const MorphUniforms u = uniforms(morph, 0.7f);
    const std::vector<vec3> p = points(11);
    for (size_t b = 0; b < p.size(); b += LANES) {
      const V3x8 v = gather(p, int(b));
      const V3x8 q8 = toObjectSpace(v, u);
      const F8 torus = mapTorus(q8), mug = mapMug(q8), object = mapObject(v, u),
               pedestal = mapPedestal(v);
      for (int i = 0; i < LANES; ++i) {
        const vec3 q = toObjectSpace(p[b + i], u);
        ASSERT_TRUE(sameBits(q.x, q8.x[i]) && sameBits(q.y, q8.y[i]) && sameBits(q.z, q8.z[i]));
        ASSERT_TRUE(sameBits(mapTorus(q), torus[i])) << "morph " << morph;
        ASSERT_TRUE(sameBits(mapMug(q), mug[i])) << "morph " << morph;
        ASSERT_TRUE(sameBits(mapObject(p[b + i], u), object[i])) << "morph " << morph;
        ASSERT_TRUE(sameBits(mapPedestal(p[b + i]), pedestal[i]));
      }
    }
  }
}

TEST(SdfMorphLanes, BoundedSceneAndIsObjectGiveTheScalarBits) {
  int bound_lanes = 0, exact_lanes = 0;
  for (bool naive : {false, true})
    for (float morph : MORPHS) {
      const MorphUniforms u = uniforms(morph, -2.1f, naive);
      const std::vector<vec3> p = points(23);
      for (size_t b = 0; b < p.size(); b += LANES) {
        const V3x8 v = gather(p, int(b));
        // A per-lane margin, as the soft shadow uses, and the fixed one of the marches.
        F8 margin;
        for (int i = 0; i < LANES; ++i) margin[i] = 0.05f * float(i);
        M8 exact8, fixed_exact8;
        const F8 d8 = mapSceneBounded(v, u, margin, exact8);
        const F8 fixed8 = mapSceneBounded(v, u, OBJECT_BOUND_MARGIN, fixed_exact8);
        const M8 object8 = isObject(v, u);
        for (int i = 0; i < LANES; ++i) {
          bool exact, fixed_exact;
          const float d = mapSceneBounded(p[b + i], u, margin[i], exact);
          const float fixed = mapSceneBounded(p[b + i], u, OBJECT_BOUND_MARGIN, fixed_exact);
          ASSERT_TRUE(sameBits(d, d8[i])) << "morph " << morph << " naive " << naive;
          ASSERT_EQ(exact, lane(exact8, i));
          ASSERT_TRUE(sameBits(fixed, fixed8[i]));
          ASSERT_EQ(fixed_exact, lane(fixed_exact8, i));
          ASSERT_EQ(isObject(p[b + i], u), lane(object8, i));
          (exact ? exact_lanes : bound_lanes) += 1;
        }
      }
    }
  // Both sides of the bound's select were exercised.
  EXPECT_GT(bound_lanes, 1000);
  EXPECT_GT(exact_lanes, 1000);
}

TEST(SdfMorphLanes, DistanceFunctionsScalarEqualsLanes) {
  const MorphUniforms u = uniforms(0.4f, 1.3f);
  const std::vector<DistanceFunction> fns = morphDistanceFunctions(u);
  ASSERT_EQ(fns.size(), 2u);
  EXPECT_EQ(fns[0].name, "mapScene");
  EXPECT_EQ(fns[1].name, "mapObject");
  const std::vector<vec3> p = points(5);
  std::vector<float> x, y, z;
  for (const vec3& q : p) {
    x.push_back(q.x);
    y.push_back(q.y);
    z.push_back(q.z);
  }
  const int n = int(p.size());
  for (const DistanceFunction& f : fns) {
    std::vector<float> a(n), b(n);
    f.scalar(x.data(), y.data(), z.data(), a.data(), n);
    f.lanes(x.data(), y.data(), z.data(), b.data(), n);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), n * sizeof(float)), 0) << f.name;
  }
  // They are the scene's functions: mapObject alone, mapScene with the pedestal and the bound.
  bool exact;
  std::vector<float> object(n), scene(n);
  fns[1].scalar(x.data(), y.data(), z.data(), object.data(), n);
  fns[0].scalar(x.data(), y.data(), z.data(), scene.data(), n);
  for (int i = 0; i < n; ++i) {
    ASSERT_TRUE(sameBits(object[i], mapObject(p[i], u)));
    ASSERT_TRUE(sameBits(scene[i], mapSceneBounded(p[i], u, OBJECT_BOUND_MARGIN, exact)));
  }
}

// The studio in lanes: directions all around, soft boxes seen and hidden within one packet.
TEST(SdfMorphLanes, StudioGivesTheScalarBits) {
  FrameContext ctx;
  ctx.params = ParamValues(&find_scene("sdf_morph")->params);
  const MorphUniforms u = make_morph_uniforms(ctx);
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  int lit_by_box = 0;
  for (int b = 0; b < 4000; ++b) {
    V3x8 d;
    for (int i = 0; i < LANES; ++i) {
      // Half the lanes near the key box's axis, half anywhere.
      vec3 v(g(rng), g(rng), g(rng));
      if (i % 2 == 0) v = u.boxes[0].dir + 0.05f * v;
      d.set_lane(i, glm::normalize(v));
    }
    const V3x8 env = studio(d, u);
    for (int i = 0; i < LANES; ++i) {
      const vec3 e = environment(d.lane(i), u);
      ASSERT_TRUE(sameBits(e.x, env.x[i]) && sameBits(e.y, env.y[i]) && sameBits(e.z, env.z[i]));
      lit_by_box += e.x > 1.0f;
    }
  }
  EXPECT_GT(lit_by_box, 1000);  // the soft box's core was seen
}

}  // namespace
}  // namespace sdfreel::sdf_morph
