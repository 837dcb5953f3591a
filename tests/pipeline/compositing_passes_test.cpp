// Compositing passes of a frame ([output] passes, render/compositing_passes.h): the samples pass
// is what the backend sampled, the sdf_evals pass adds up to the frame's own count and is the same
// on the CPU's packet and single-ray paths, and asking for passes changes no pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "pipeline/frame_pipeline.h"
#include "render/camera.h"
#include "scenes/registry.h"
#include "scenes/scene_passes.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

Timeline small_timeline(const std::string& scene, const std::string& sampling,
                        const std::string& passes) {
  const std::string text = "[video]\nscene = \"" + scene +
                           "\"\nfps = 24\nduration = 1\nresolution = [48, 27]\n" + sampling +
                           "\n[output]\nframes = [\"exr\"]\n" + passes + "\n";
  return parse_timeline(all_scenes(), "passes.toml", text, nullptr, nullptr);
}

// By a plain string: a std::string temporary would make GCC 14 warn of a dangling reference.
const PassImage& pass_named(const RenderedFrame& f, const char* name) {
  for (const PassImage& p : f.passes)
    if (p.name == name) return p;
  throw std::runtime_error(std::string("no pass ") + name);
}

// A frame's depth, normal and id passes, rendered on the CPU at 48x27.
struct SurfacePasses {
  RenderedFrame f;
  std::vector<float> z, n, id;  // n: three values a pixel
  glm::vec3 normal(size_t i) const { return glm::vec3(n[i * 3], n[i * 3 + 1], n[i * 3 + 2]); }
};

SurfacePasses surface_passes(const std::string& scene, const std::string& sampling, int frame) {
  const Timeline tl = small_timeline(scene, sampling, "passes = [\"depth\", \"normal\", \"id\"]");
  FramePipeline pipe(tl, std::make_unique<CpuBackend>(2));
  SurfacePasses s{pipe.render(frame), {}, {}, {}};
  s.z = pass_named(s.f, "depth").values;
  s.n = pass_named(s.f, "normal").values;
  s.id = pass_named(s.f, "id").values;
  EXPECT_EQ(pass_named(s.f, "normal").channels, (std::vector<std::string>{"N.X", "N.Y", "N.Z"}));
  return s;
}

TEST(CompositingPasses, EvalsAddUpToTheFrameCountOnBothCpuPathsInEveryScene) {
  for (const SceneInfo& scene : all_scenes()) {
    if (!scene.counts_sdf_evals) continue;
    const Timeline tl =
        small_timeline(scene.name, "samples = 2", "passes = [\"sdf_evals\", \"samples\"]");
    std::vector<std::vector<float>> evals;
    for (bool packets : {true, false}) {
      FramePipeline pipe(tl, std::make_unique<CpuBackend>(2, 16, packets));
      const RenderedFrame f = pipe.render(5);
      ASSERT_EQ(f.passes.size(), 2u);
      EXPECT_EQ(f.passes[0].name, "sdf_evals");  // in the order asked for
      const PassImage& e = pass_named(f, "sdf_evals");
      ASSERT_EQ(e.values.size(), size_t(48 * 27));
      double sum = 0.0;
      for (float v : e.values) {
        ASSERT_GE(v, 0.0f);
        ASSERT_EQ(v, std::floor(v));
        sum += v;
      }
      EXPECT_GT(sum, 0.0) << scene.name;
      EXPECT_EQ(sum, double(f.stats.sdf_evals)) << scene.name << (packets ? " packets" : " rays");
      for (float v : pass_named(f, "samples").values) ASSERT_EQ(v, 2.0f);
      evals.push_back(e.values);
    }
    EXPECT_EQ(evals[0], evals[1]) << scene.name << ": packets and single rays count differently";
  }
}

// Every pass a scene gives is the same from the CPU's packets as from its single rays.
TEST(CompositingPasses, PacketsAndSingleRaysGiveTheSamePassesInEveryScene) {
  for (const SceneInfo& scene : all_scenes()) {
    if (!scene.make) continue;
    std::string names;
    for (const std::string& p : scene_passes(scene))
      names += (names.empty() ? "\"" : ", \"") + p + "\"";
    const Timeline tl = small_timeline(scene.name, "samples = 2", "passes = [" + names + "]");
    FramePipeline packets(tl, std::make_unique<CpuBackend>(2, 16, true));
    FramePipeline rays(tl, std::make_unique<CpuBackend>(2, 16, false));
    const RenderedFrame a = packets.render(7), b = rays.render(7);
    ASSERT_EQ(a.passes.size(), scene_passes(scene).size());
    for (size_t i = 0; i < a.passes.size(); ++i)
      EXPECT_EQ(a.passes[i].values, b.passes[i].values) << scene.name << ": " << a.passes[i].name;
  }
}

// The id pass names the surface under each pixel's centre, in the scene's numbering: sdf_morph's
// object (1) and pedestal (2) where the default camera sees them, nothing (0) above them.
TEST(CompositingPasses, IdIsTheSurfaceAtThePixelsCentre) {
  const Timeline tl = small_timeline("sdf_morph", "samples = 3", "passes = [\"id\"]");
  FramePipeline pipe(tl, std::make_unique<CpuBackend>(2));
  const RenderedFrame f = pipe.render(5);
  const std::vector<float>& id = pass_named(f, "id").values;
  EXPECT_EQ(id[8 * 48 + 22], 1.0f);   // the morphing object
  EXPECT_EQ(id[18 * 48 + 24], 2.0f);  // its pedestal
  EXPECT_EQ(id[0], 0.0f);             // the studio behind
  for (float v : id) ASSERT_TRUE(v == 0.0f || v == 1.0f || v == 2.0f) << v;
  // One ray through each centre in hit-mask mode: exactly that render of the frame's context.
  FrameContext ctx = f.ctx;
  ctx.samples = 1;
  finish_frame_context(ctx);
  ctx.march.hit_mask = true;
  CpuBackend cpu(1);
  cpu.begin(pipe.scene());
  RayStats stats;
  const ImageRGBA mask = cpu.render(ctx, stats);
  for (size_t i = 0; i < id.size(); ++i) ASSERT_EQ(id[i], mask.pixels[i * 4]) << i;
}

// Depth and normal at known surfaces: where sdf_morph's camera sees the floor (y = 0), the normal
// is (0, 1, 0) and the depth the floor's distance from the camera's plane; the object's normals
// are unit vectors and its depths nearer than the floor behind it; the sky is 1e10 and no normal.
TEST(CompositingPasses, DepthAndNormalOfTheFloorAndTheObject) {
  const SurfacePasses s = surface_passes("sdf_morph", "samples = 2", 5);
  const std::vector<float>&z = s.z, &id = s.id;
  const RenderedFrame& f = s.f;
  const CameraBasis& cam = f.ctx.camera;
  int floor = 0, object = 0, sky = 0;
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x) {
      const size_t i = size_t(y) * 48 + x;
      const glm::vec3 normal = s.normal(i);
      const glm::vec3 dir = primary_ray_dir(cam, x + 0.5f, y + 0.5f, 48, 27);
      if (id[i] == 0.0f && normal == glm::vec3(0.0f, 1.0f, 0.0f)) {  // the floor
        const float t = -cam.origin.y / dir.y;
        EXPECT_NEAR(z[i], t * glm::dot(dir, cam.forward), 1e-5f * z[i]) << x << ", " << y;
        ++floor;
      } else if (id[i] == 1.0f) {
        EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f);
        EXPECT_LT(glm::dot(normal, dir), 0.1f);  // it faces the camera
        EXPECT_GT(z[i], 2.0f);
        EXPECT_LT(z[i], 5.0f);
        ++object;
      } else if (id[i] == 0.0f && z[i] == 1e10f) {
        EXPECT_EQ(normal, glm::vec3(0.0f));
        ++sky;
      }
    }
  EXPECT_GT(floor, 100);
  EXPECT_GT(object, 20);
  EXPECT_GT(sky, 100);
}

// The lanterns' lake is nearly level (its waves are small against their length): its normals point
// up, every normal is unit length and faces the camera (but at a few silhouette pixels, where a
// finite-difference normal of a grazing hit may lean away), and the sky has no surface.
TEST(CompositingPasses, DepthAndNormalOfTheLakeAndTheLanterns) {
  const SurfacePasses s = surface_passes("lantern_festival", "samples = 1", 5);
  const std::vector<float>&z = s.z, &id = s.id;
  const RenderedFrame& f = s.f;
  int lake = 0, lanterns = 0, sky = 0, leaning_away = 0;
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x) {
      const size_t i = size_t(y) * 48 + x;
      const glm::vec3 normal = s.normal(i);
      const glm::vec3 dir = primary_ray_dir(f.ctx.camera, x + 0.5f, y + 0.5f, 48, 27);
      if (id[i] == 0.0f) {
        EXPECT_EQ(z[i], 1e10f);
        EXPECT_EQ(normal, glm::vec3(0.0f));
        ++sky;
        continue;
      }
      EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f) << x << ", " << y;
      leaning_away += glm::dot(normal, dir) >= 0.0f;
      EXPECT_GT(z[i], 0.0f);
      EXPECT_LT(z[i], 1e4f);
      if (id[i] == 2.0f) {
        EXPECT_GT(normal.y, 0.9f) << x << ", " << y;
        ++lake;
      } else {
        ++lanterns;
      }
    }
  EXPECT_GT(lake, 100);
  EXPECT_GT(lanterns, 10);
  EXPECT_GT(sky, 100);
  EXPECT_LE(leaning_away * 50, lake + lanterns);  // at most 2%
}

// The lenticular card's boxes meet rays analytically: every face seen faces the camera, with a
// unit normal of the card's frame (level, or straight up); its floor is the plane y = 0.
TEST(CompositingPasses, DepthAndNormalOfTheCardAndItsFloor) {
  const SurfacePasses s = surface_passes("lenticular_card", "samples = 1", 5);
  const std::vector<float>&z = s.z, &id = s.id;
  const RenderedFrame& f = s.f;
  const CameraBasis& cam = f.ctx.camera;
  int floor = 0, card = 0;
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x) {
      const size_t i = size_t(y) * 48 + x;
      const glm::vec3 normal = s.normal(i);
      const glm::vec3 dir = primary_ray_dir(cam, x + 0.5f, y + 0.5f, 48, 27);
      if (id[i] == 0.0f && z[i] < 1e10f) {
        EXPECT_EQ(normal, glm::vec3(0.0f, 1.0f, 0.0f));
        const float t = -cam.origin.y / dir.y;
        EXPECT_NEAR(z[i], t * glm::dot(dir, cam.forward), 1e-5f * z[i]) << x << ", " << y;
        ++floor;
      } else if (id[i] != 0.0f) {
        EXPECT_NEAR(glm::length(normal), 1.0f, 1e-6f);
        EXPECT_TRUE(normal.y == 0.0f || std::fabs(normal.y) == 1.0f) << normal.y;
        EXPECT_LT(glm::dot(normal, dir), 0.0f) << x << ", " << y;
        EXPECT_GT(z[i], 0.5f);
        EXPECT_LT(z[i], 10.0f);
        card += id[i] == 1.0f;
      }
    }
  EXPECT_GT(floor, 50);
  EXPECT_GT(card, 50);
}

// The fur's room and case are axis-aligned boxes: their normals are exactly the axes; the furry
// shapes (ids 1 to 3) have unit normals, and every surface lies in the room (depth 0.1 to 20 m).
TEST(CompositingPasses, DepthAndNormalOfTheFurCase) {
  const SurfacePasses s = surface_passes("fur", "samples = 1", 6);
  const std::vector<float>&z = s.z, &id = s.id;
  int boxes = 0, shapes = 0;
  for (size_t i = 0; i < id.size(); ++i) {
    const glm::vec3 normal = s.normal(i);
    if (z[i] == 1e10f) continue;
    EXPECT_GT(z[i], 0.1f);
    EXPECT_LT(z[i], 20.0f);
    EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f);
    if (id[i] == 0.0f) {
      EXPECT_EQ((normal.x == 0.0f) + (normal.y == 0.0f) + (normal.z == 0.0f), 2) << i;
      ++boxes;
    } else {
      ++shapes;
    }
  }
  EXPECT_GT(boxes, 200);
  EXPECT_GT(shapes, 20);
}

// The museum's hall is axis-aligned boxes: its normals are exactly the axes, and where it shows its
// floor (y = 0) the depth is the analytic plane's; exhibit 1 (marched) and the card have unit
// normals facing the camera; the window's sky is no surface.
TEST(CompositingPasses, DepthAndNormalOfTheMuseumsHallAndExhibits) {
  const SurfacePasses s = surface_passes("museum", "samples = 1", 6);
  const std::vector<float>&z = s.z, &id = s.id;
  const CameraBasis& cam = s.f.ctx.camera;
  int floor = 0, hall = 0, exhibits = 0, sky = 0;
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x) {
      const size_t i = size_t(y) * 48 + x;
      const glm::vec3 normal = s.normal(i);
      const glm::vec3 dir = primary_ray_dir(cam, x + 0.5f, y + 0.5f, 48, 27);
      if (z[i] == 1e10f) {
        EXPECT_EQ(normal, glm::vec3(0.0f));
        ++sky;
        continue;
      }
      EXPECT_GT(z[i], 0.05f);
      EXPECT_LT(z[i], 30.0f);
      EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f) << x << ", " << y;
      if (id[i] == 2.0f) {
        EXPECT_EQ((normal.x == 0.0f) + (normal.y == 0.0f) + (normal.z == 0.0f), 2)
            << x << ", " << y;
        const float floor_t = -cam.origin.y / dir.y;
        const float hit_y = cam.origin.y + dir.y * (z[i] / glm::dot(dir, cam.forward));
        if (normal.y == 1.0f && std::fabs(hit_y) < 0.01f) {
          EXPECT_NEAR(z[i], floor_t * glm::dot(dir, cam.forward), 1e-3f * z[i]) << x << ", " << y;
          ++floor;
        }
        ++hall;
      } else if (id[i] == 1.0f || id[i] == 3.0f) {
        EXPECT_LT(glm::dot(normal, dir), 0.1f) << x << ", " << y;
        ++exhibits;
      }
    }
  EXPECT_GT(floor, 50);
  EXPECT_GT(hall, 400);
  EXPECT_GT(exhibits, 3);
  EXPECT_GT(sky, 3);  // the window
}

// The docs' example (docs/passes.png) asks for what its scene gives.
TEST(CompositingPasses, TheDocsExampleLoads) {
  const Timeline tl = load_timeline(
      all_scenes(), std::string(SDFREEL_SOURCE_DIR) + "/examples/passes.toml", nullptr);
  EXPECT_EQ(tl.frame_options.passes, (std::vector<std::string>{"depth", "normal", "id"}));
  EXPECT_EQ(tl.frame_count(), 1);
}

// An adaptive frame of a plan of several passes (the museum) and of one ray pass (the lanterns):
// the samples pass is the backend's count, and the picture is the one rendered without passes.
TEST(CompositingPasses, SamplesAreTheBackendsCountsAndPassesChangeNoPixel) {
  for (const std::string scene : {"museum", "lantern_festival"}) {
    const std::string sampling = "adaptive = { minimum = 1, maximum = 6, threshold = 0.02 }";
    const Timeline with = small_timeline(scene, sampling, "passes = [\"samples\", \"id\"]");
    const Timeline without = small_timeline(scene, sampling, "");
    FramePipeline pipe(with, std::make_unique<CpuBackend>(2));
    const RenderedFrame f = pipe.render(3);
    const SampleCounts& counts = f.sample_counts;  // the frame's, not the id render's
    const PassImage& samples = pass_named(f, "samples");
    EXPECT_EQ(samples.channels, std::vector<std::string>{"samples"});
    ASSERT_EQ(samples.values.size(), counts.size());
    for (size_t i = 0; i < counts.size(); ++i) ASSERT_EQ(samples.values[i], float(counts[i]));
    const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
    EXPECT_EQ(*lo, 1) << scene;  // adaptive: the counts vary
    EXPECT_GT(*hi, 1) << scene;
    FramePipeline plain(without, std::make_unique<CpuBackend>(2));
    const RenderedFrame g = plain.render(3);
    EXPECT_TRUE(g.passes.empty());
    EXPECT_EQ(f.linear_hash, g.linear_hash) << scene;
    EXPECT_EQ(f.display_md5, g.display_md5) << scene;
  }
}

}  // namespace
}  // namespace sdfreel
