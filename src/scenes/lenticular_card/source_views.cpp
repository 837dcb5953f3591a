#include "scenes/lenticular_card/source_views.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "io/cache_file.h"
#include "render/camera_lanes.h"
#include "render/quality.h"
#include "scenes/lenticular_card/ppm.h"
#include "scenes/registry.h"
#include "sdf/det_math.h"

namespace sdfreel::lenticular_card {
namespace {

const SceneInfo& scene_of(const ViewSet& set) {
  const SceneInfo* info = find_scene(set.scene);
  if (!info || !info->make)
    throw std::runtime_error("lenticular_card: no scene '" + set.scene + "'");
  return *info;
}

FrameContext view_context(const ViewSet& set, const SceneInfo& info, int i) {
  FrameContext ctx;
  ctx.width = set.width;
  ctx.height = set.height;
  ctx.samples = set.samples;
  ctx.scene_time = set.time;
  ctx.quality = Quality::Final;
  ctx.pose = view_pose(set, i);
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  return ctx;
}

// What a print carries: exposure 1 - exp(-x), then the sRGB curve, rounded to 8 bits.
uint8_t print_byte(float linear) {
  const float exposed = 1.0f - dm::exp(-dm::max(linear, 0.0f));
  const float encoded =
      exposed <= 0.0031308f ? 12.92f * exposed : 1.055f * dm::pow(exposed, 1.0f / 2.4f) - 0.055f;
  return uint8_t(dm::floor(dm::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f));
}

// A frame plan of ray passes into "colour" (what every scene's plan is so far), run ray by ray.
void check_plan(const FramePlan& plan, const std::string& scene) {
  for (const Pass& pass : plan.passes) {
    const RayPass* ray = std::get_if<RayPass>(&pass);
    if (!ray || ray->colour != COLOUR_TARGET || !ray->depth.empty() || !ray->scalar)
      throw std::runtime_error("lenticular_card: scene '" + scene + "' has pass '" +
                               pass_name(pass) + "', not a plain ray pass: it cannot be a source");
  }
}

}  // namespace

CameraPose view_pose(const ViewSet& set, int i) {
  const SceneInfo& info = scene_of(set);
  CameraPose pose = info.default_camera;
  const double fraction = set.views > 1 ? double(i) / double(set.views - 1) - 0.5 : 0.0;
  const float angle = float(fraction * set.orbit_deg * 0.017453292519943295);
  // Rotation about +Y: positive angles move the eye toward the camera's right.
  const double c = dm::cos(angle), s = dm::sin(angle);
  const glm::dvec3 o = pose.position - pose.target;
  pose.position = pose.target + glm::dvec3(o.x * c + o.z * s, o.y, -o.x * s + o.z * c);
  pose.fov_deg = pose.fov_deg / set.zoom;
  return pose;
}

std::string view_key(const ViewSet& set, int i) {
  const CameraPose p = view_pose(set, i);
  char text[512];
  std::snprintf(text, sizeof text,
                "%s view %d/%d %dx%d s%d t%.17g pos %.17g %.17g %.17g at %.17g %.17g %.17g fov "
                "%.17g roll %.17g",
                set.scene.c_str(), i, set.views, set.width, set.height, set.samples, set.time,
                p.position.x, p.position.y, p.position.z, p.target.x, p.target.y, p.target.z,
                p.fov_deg, p.roll_deg);
  return text;
}

namespace {

// A one-pass plan through its eight-lane code: each row's (pixel, sample) pairs eight at a time
// (the last packet padded with its last pair), each pixel's samples added in list order. The
// lanes give the scalar code's bits (tests/scenes/packet_path_test.cpp), about five times faster.
void sum_in_packets(const RayPass& pass, const FrameContext& ctx, float pixel_angle,
                    std::vector<glm::vec3>& sum) {
  const int samples = int(ctx.sample_offsets.size()), pairs = ctx.width * samples;
  tbb::parallel_for(0, ctx.height, [&](int y) {
    RayPassOutput out;
    RayStats stats;
    for (int base = 0; base < pairs; base += LANES) {
      const int count = std::min(LANES, pairs - base);
      F8 px, py;
      for (int k = 0; k < LANES; ++k) {
        const int pair = base + std::min(k, count - 1);
        const glm::vec2& offset = ctx.sample_offsets[size_t(pair % samples)];
        px[k] = float(pair / samples) + offset.x;
        py[k] = float(y) + offset.y;
      }
      out.start();
      pass.packet(primary_packet(ctx.camera, pixel_angle, px, py, count, ctx.width, ctx.height),
                  out, stats);
      // A lane the pass does not keep adds nothing, as the untouched black of the ray-by-ray
      // path does.
      for (int k = 0; k < count; ++k)
        if (out.keep[k]) sum[size_t(y) * ctx.width + (base + k) / samples] += out.colour[k];
    }
  });
}

// Any plan of ray passes, ray by ray, each pass handed the colour the one before left.
void sum_ray_by_ray(const FramePlan& plan, const FrameContext& ctx, float pixel_angle,
                    std::vector<glm::vec3>& sum) {
  // Rows in parallel, each pixel's samples in list order: the same bits on any thread count.
  tbb::parallel_for(0, ctx.height, [&](int y) {
    for (int x = 0; x < ctx.width; ++x)
      for (const glm::vec2& offset : ctx.sample_offsets) {
        const glm::vec3 dir = primary_ray_dir(ctx.camera, float(x) + offset.x, float(y) + offset.y,
                                              ctx.width, ctx.height);
        glm::vec3 colour(0.0f);
        float depth = 1.0f;
        bool keep = false;
        RayStats stats;
        for (const Pass& pass : plan.passes)
          std::get<RayPass>(pass).scalar(Ray{ctx.camera.origin, dir, pixel_angle}, colour, depth,
                                         keep, stats);
        sum[size_t(y) * ctx.width + x] += colour;
      }
  });
}

}  // namespace

Rgb8Image render_view(const ViewSet& set, int i) {
  const SceneInfo& info = scene_of(set);
  const FrameContext ctx = view_context(set, info, i);
  std::unique_ptr<Scene> scene = info.make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  check_plan(plan, set.scene);
  const float pixel_angle = footprint_angle(ctx.camera.tan_half_fov, ctx.height);
  std::vector<glm::vec3> sum(size_t(ctx.width) * ctx.height, glm::vec3(0.0f));
  const RayPass* only = plan.passes.size() == 1 ? &std::get<RayPass>(plan.passes[0]) : nullptr;
  if (only && only->packet)
    sum_in_packets(*only, ctx, pixel_angle, sum);
  else
    sum_ray_by_ray(plan, ctx, pixel_angle, sum);
  const float inv = 1.0f / float(ctx.sample_offsets.size());
  Rgb8Image img(ctx.width, ctx.height);
  for (size_t p = 0; p < sum.size(); ++p)
    for (int c = 0; c < 3; ++c) img.rgb[p * 3 + c] = print_byte(sum[p][c] * inv);
  return img;
}

std::vector<Rgb8Image> source_views(const ViewSet& set) {
  std::vector<Rgb8Image> views;
  for (int i = 0; i < set.views; ++i) {
    const std::string key = view_key(set, i);
    Rgb8Image img(set.width, set.height);
    const auto cached = read_cache_file("lenticular", key);
    if (cached && cached->size() == img.rgb.size()) {
      std::copy(cached->begin(), cached->end(), img.rgb.begin());
    } else {
      img = render_view(set, i);
      write_cache_file("lenticular", key, std::vector<char>(img.rgb.begin(), img.rgb.end()));
    }
    views.push_back(std::move(img));
  }
  return views;
}

}  // namespace sdfreel::lenticular_card
