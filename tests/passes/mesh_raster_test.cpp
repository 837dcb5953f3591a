// The CPU mesh pass against the plain per-pixel rule (reference_rasteriser.h): on random,
// degenerate, sliver, huge, near-clipped and pixel-centre triangles, at several tile sizes and
// thread counts, shaded one fragment or eight at a time, the same pixels get the same colour
// (varyings) and depth bits; and a grid of
// triangles with its vertices on pixel centres covers each pixel exactly once (the top-left rule).
#include <gtest/gtest.h>

#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>

#include "backends/cpu/plan_runner.h"
#include "passes/plan_fixture.h"
#include "passes/reference_rasteriser.h"

namespace sdfreel {
namespace {

struct MeshBuilder {
  TriangleMesh m;
  std::mt19937 rng{7};
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
  void vertex(const glm::vec3& p) {
    m.positions.insert(m.positions.end(), {p.x, p.y, p.z});
    m.normals.insert(m.normals.end(), {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
    m.uvs.insert(m.uvs.end(), {uniform(0, 1), uniform(0, 1)});
  }
  void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    vertex(a), vertex(b), vertex(c);
  }
};

// A pass drawing `mesh` in clip space = projection * position (so w = 1 without a perspective),
// with every varying in its colour.
MeshPass test_pass(TriangleMesh mesh, const glm::mat4& projection, CullMode cull) {
  MeshPass p;
  p.name = "raster test";
  p.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  p.colour = "colour";
  p.depth = "depth";
  p.cull = cull;
  p.view = PassView{glm::mat4(1.0f), projection};
  p.shade = [](const MeshFragment& f) {
    return glm::vec4(f.uv.x + f.instance_data.x, f.uv.y + f.world_position.x,
                     f.world_position.z + f.world_normal.x, f.front_facing ? 1.0f : 0.5f);
  };
  return p;
}

// `pass` shaded eight fragments at a time as well (MeshPass::shade8, the rasteriser's lanes path):
// the test colour with alpha = u, half of it discarded by the cutoff.
MeshPass with_lanes(MeshPass p) {
  p.alpha_cutoff = 0.5f;
  p.shade = [](const MeshFragment& f) {
    return glm::vec4(f.uv.x + f.instance_data.x, f.uv.y + f.world_position.x,
                     f.world_position.z + f.world_normal.x, f.uv.x);
  };
  p.shade8 = [](const MeshFragments8& f, FragmentColours8& c) {
    c.r = f.uv.x + f.instance_data.x;
    c.g = f.uv.y + f.world_position.x;
    c.b = f.world_position.z + f.world_normal.x;
    c.a = f.uv.x;
  };
  return p;
}

// Runs `pass` at every tile size and thread count and expects the reference's bits.
void expect_reference_bits(const MeshPass& pass, int width, int height) {
  const test::ReferenceImages want = test::reference_mesh_pass(pass, width, height);
  const FrameContext ctx = test::plan_context(width, height);
  for (int tile : {16, 7, 1})
    for (int threads : {1, 2}) {
      CpuPassContext pc{
          ctx,  glm::vec2(0.5f), make_camera_model(ctx.camera, width, height, 0.1f, 100.0f),
          0.0f, threads,         tile,
          true};
      CpuTargets targets({{"colour", TargetKind::Colour}, {"depth", TargetKind::Depth}}, width,
                         height);
      targets.clear();
      MeshPassCache cache;
      run_mesh_pass(pass, pc, targets, cache);
      const ImageRGBA& colour = targets.get("colour", "test");
      const ImageRGBA& depth = targets.get("depth", "test");
      EXPECT_EQ(0, std::memcmp(colour.pixels.data(), want.colour.pixels.data(),
                               colour.pixels.size() * sizeof(float)))
          << "colour, tile " << tile << ", threads " << threads;
      EXPECT_EQ(0, std::memcmp(depth.pixels.data(), want.depth.pixels.data(),
                               depth.pixels.size() * sizeof(float)))
          << "depth, tile " << tile << ", threads " << threads;
    }
}

int drawn_pixels(const test::ReferenceImages& r) {
  int n = 0;
  for (size_t i = 3; i < r.colour.pixels.size(); i += 4) n += r.colour.pixels[i] > 0.0f;
  return n;
}

TEST(MeshRaster, RandomOverlappingTrianglesGiveTheReferenceBits) {
  MeshBuilder b;
  for (int i = 0; i < 300; ++i) {
    auto p = [&] {
      return glm::vec3(b.uniform(-1.3f, 1.3f), b.uniform(-1.3f, 1.3f), b.uniform(-1, 1));
    };
    const glm::vec3 a = p();
    // Mostly small triangles, as a fine mesh gives, some large.
    const float s = i % 10 == 0 ? 1.0f : 0.05f;
    b.triangle(a, a + (p() - a) * s, a + (p() - a) * s);
  }
  for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front}) {
    MeshPass pass = test_pass(b.m, glm::mat4(1.0f), cull);
    pass.instances = {
        {glm::mat4(1.0f), glm::vec4(0.0f)},
        {glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, -0.05f, 0.2f)), glm::vec4(2.0f)}};
    EXPECT_GT(drawn_pixels(test::reference_mesh_pass(pass, 61, 37)), 500);
    expect_reference_bits(pass, 61, 37);
    expect_reference_bits(with_lanes(pass), 61, 37);
  }
}

TEST(MeshRaster, PerspectiveAndNearClippedTrianglesGiveTheReferenceBits) {
  MeshBuilder b;
  for (int i = 0; i < 200; ++i) {
    // Some vertices behind the camera (z > -near): those triangles are clipped; some beyond the
    // far plane: their pixels there are dropped.
    auto p = [&] { return glm::vec3(b.uniform(-6, 6), b.uniform(-4, 4), b.uniform(-30, 1)); };
    b.triangle(p(), p(), p());
  }
  const glm::mat4 projection = glm::perspective(0.9f, 48.0f / 27.0f, 0.5f, 20.0f);
  MeshPass pass = test_pass(b.m, projection, CullMode::None);
  EXPECT_GT(drawn_pixels(test::reference_mesh_pass(pass, 48, 27)), 400);
  expect_reference_bits(pass, 48, 27);
  expect_reference_bits(with_lanes(pass), 48, 27);
  // Enough instances that the pass sets up in several batches (on several threads); without a
  // depth test the last triangle drawn wins, so the batches must be drawn in mesh order.
  pass.depth_test = DepthTest::Off;
  pass.instances.clear();
  for (int i = 0; i < 100; ++i)
    pass.instances.push_back(
        {glm::translate(glm::mat4(1.0f), glm::vec3(0.05f * float(i % 10), 0.0f, -0.1f * float(i))),
         glm::vec4(float(i))});
  expect_reference_bits(pass, 48, 27);
}

TEST(MeshRaster, DegenerateSliverAndHugeTrianglesGiveTheReferenceBits) {
  MeshBuilder b;
  const glm::vec3 a(-0.8f, -0.7f, 0.1f), c(0.9f, 0.6f, 0.3f);
  b.triangle(a, c, a + (c - a) * 0.5f);                           // collinear: no area
  b.triangle(a, a, c);                                            // repeated vertex
  b.triangle(a, c, a + (c - a) * 0.5f + glm::vec3(1e-4f, 0, 0));  // slivers, both windings
  b.triangle(a, a + (c - a) * 0.3f + glm::vec3(0, 2e-3f, 0), c);
  b.triangle(glm::vec3(-0.9f, 0.02f, 0), glm::vec3(0.9f, 0.021f, 0), glm::vec3(0.9f, 0.0205f, 0));
  b.triangle(glm::vec3(-1e4f, -1e4f, 0.5f), glm::vec3(1e4f, -1e4f, 0.5f),
             glm::vec3(0.0f, 1e4f, 0.5f));  // covers the frame many times over
  b.triangle(glm::vec3(-3e4f, 5.0f, 0.2f), glm::vec3(3e4f, 5.0f, 0.2f),
             glm::vec3(0.0f, -2e4f, 0.2f));  // the frame near one of its edges
  b.triangle(glm::vec3(2.0f, 2.0f, 0), glm::vec3(3.0f, 2.0f, 0), glm::vec3(2.0f, 3.0f, 0));  // off
  const MeshPass pass = test_pass(b.m, glm::mat4(1.0f), CullMode::None);
  EXPECT_GT(drawn_pixels(test::reference_mesh_pass(pass, 40, 23)), 40 * 23 / 2);
  expect_reference_bits(pass, 40, 23);
  expect_reference_bits(with_lanes(pass), 40, 23);
}

// Vertices exactly on pixel centres (window (i + 0.5, j + 0.5): dyadic clip coordinates at a
// 64x32 frame), so edges run through centres horizontally, vertically and diagonally; cells of 3
// pixels and of 12 (rows the rasteriser narrows to the edges' crossings before testing).
class MeshRasterGrid : public testing::TestWithParam<int> {};

TEST_P(MeshRasterGrid, ThroughPixelCentresCoversEachPixelOnceAndGivesTheReferenceBits) {
  constexpr int W = 64, H = 32;
  const int STEP = GetParam();
  MeshBuilder b;
  auto centre = [](int i, int j) {
    return glm::vec3((2.0f * float(i) + 1.0f) / W - 1.0f, (2.0f * float(j) + 1.0f) / H - 1.0f,
                     0.25f * float((i + j) % 3) - 0.4f);
  };
  for (int j = 0; j + STEP < H; j += STEP)
    for (int i = 0; i + STEP < W; i += STEP) {
      const glm::vec3 p00 = centre(i, j), p10 = centre(i + STEP, j), p01 = centre(i, j + STEP),
                      p11 = centre(i + STEP, j + STEP);
      if ((i + j) % 2) {
        b.triangle(p00, p10, p11), b.triangle(p00, p11, p01);
      } else {
        b.triangle(p00, p10, p01), b.triangle(p10, p11, p01);
      }
    }
  MeshPass pass = test_pass(b.m, glm::mat4(1.0f), CullMode::Back);
  pass.depth_test = DepthTest::Off;
  const test::ReferenceImages want = test::reference_mesh_pass(pass, W, H);
  const int last = (H - 1 - STEP) / STEP * STEP + STEP, right = (W - 1 - STEP) / STEP * STEP + STEP;
  for (int wy = 0; wy < H; ++wy)
    for (int wx = 0; wx < W; ++wx) {
      // The top-left rule: the grid's left column and top row are its own, its right column and
      // bottom row (window row 0) are not.
      const bool inside = wx < right && wy > 0 && wy <= last;
      EXPECT_EQ(inside ? 1 : 0, want.covered[size_t((H - 1 - wy) * W + wx)])
          << "pixel " << wx << ", window row " << wy;
    }
  expect_reference_bits(pass, W, H);
  expect_reference_bits(with_lanes(pass), W, H);
}

INSTANTIATE_TEST_SUITE_P(Cells, MeshRasterGrid, testing::Values(3, 12));

}  // namespace
}  // namespace sdfreel
