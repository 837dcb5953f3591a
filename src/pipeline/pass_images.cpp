#include "pipeline/pass_images.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

#include "render/camera.h"
#include "render/rays.h"
#include "render/sample_pattern.h"

namespace sdfreel {
namespace {

bool asked(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The frame once more, one ray through each pixel's centre, in a mode that draws something else
// than colour (MarchSettings::hit_mask, ::surface).
ImageRGBA render_at_centres(Backend& backend, const FrameContext& frame,
                            const std::function<void(MarchSettings&)>& mode) {
  FrameContext ctx = frame;
  ctx.samples = 1;
  ctx.adaptive.enabled = false;
  ctx.sample_offsets = sample_offsets(1);  // the pixel's centre
  mode(ctx.march);
  RayStats ignored;
  return backend.render(ctx, ignored);
}

// The first `channels` channels of each pixel.
std::vector<float> channels_of(const ImageRGBA& img, int channels) {
  std::vector<float> out;
  out.reserve(img.pixels.size() / 4 * size_t(channels));
  for (size_t i = 0; i < img.pixels.size(); i += 4)
    out.insert(out.end(), img.pixels.begin() + std::ptrdiff_t(i),
               img.pixels.begin() + std::ptrdiff_t(i) + channels);
  return out;
}

// Distances along the centres' rays as distances from the camera's plane (a z-buffer's depth).
std::vector<float> planar_depths(const ImageRGBA& distances, const FrameContext& ctx) {
  std::vector<float> z = channels_of(distances, 1);
  for (int y = 0; y < ctx.height; ++y)
    for (int x = 0; x < ctx.width; ++x) {
      float& v = z[size_t(y) * ctx.width + x];
      if (v == NO_SURFACE_DISTANCE) continue;
      const glm::vec3 dir =
          primary_ray_dir(ctx.camera, float(x) + 0.5f, float(y) + 0.5f, ctx.width, ctx.height);
      v *= glm::dot(dir, ctx.camera.forward);
    }
  return z;
}

}  // namespace

void record_passes(const std::vector<std::string>& names, Backend& backend) {
  backend.record_sdf_evals(asked(names, "sdf_evals"));
}

std::vector<PassImage> pass_images(const std::vector<std::string>& names, Backend& backend,
                                   const FrameContext& ctx) {
  std::vector<PassImage> out;
  const size_t pixels = size_t(ctx.width) * ctx.height;
  for (const std::string& name : names) {  // first what the frame's own render kept
    const CompositingPass* pass = find_compositing_pass(name);
    if (!pass) throw std::logic_error("unknown compositing pass '" + name + "'");
    PassImage img{name, pass->channels, ctx.width, ctx.height, {}};
    if (name == "samples") {
      const SampleCounts& counts = backend.sample_counts();
      img.values.assign(counts.begin(), counts.end());
    } else if (name == "sdf_evals") {
      img.values = backend.sdf_eval_counts();
    }
    out.push_back(std::move(img));
  }
  for (PassImage& img : out) {  // then what renders again
    if (img.name == "id")
      img.values = channels_of(
          render_at_centres(backend, ctx, [](MarchSettings& m) { m.hit_mask = true; }), 1);
    if (img.name == "depth")
      img.values = planar_depths(
          render_at_centres(backend, ctx, [](MarchSettings& m) { m.surface = SURFACE_DISTANCE; }),
          ctx);
    if (img.name == "normal")
      img.values = channels_of(
          render_at_centres(backend, ctx, [](MarchSettings& m) { m.surface = SURFACE_NORMAL; }), 3);
  }
  for (const PassImage& img : out)
    if (img.values.size() != pixels * img.channels.size())
      throw std::logic_error("the " + backend.name() + " backend kept no '" + img.name +
                             "' pass of this frame");
  return out;
}

}  // namespace sdfreel
