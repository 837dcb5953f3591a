#include "pipeline/pass_images.h"

#include <algorithm>
#include <stdexcept>

#include "render/rays.h"
#include "render/sample_pattern.h"

namespace sdfreel {
namespace {

bool asked(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The id of the surface under each pixel's centre: the frame in hit-mask mode, one sample.
std::vector<float> surface_ids(Backend& backend, const FrameContext& frame) {
  FrameContext ctx = frame;
  ctx.samples = 1;
  ctx.adaptive.enabled = false;
  ctx.sample_offsets = sample_offsets(1);  // the pixel's centre
  ctx.march.hit_mask = true;
  RayStats ignored;
  const ImageRGBA ids = backend.render(ctx, ignored);
  std::vector<float> out(ids.pixels.size() / 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = ids.pixels[i * 4];
  return out;
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
  for (PassImage& img : out)  // then what renders again
    if (img.name == "id") img.values = surface_ids(backend, ctx);
  for (const PassImage& img : out)
    if (img.values.size() != pixels * img.channels.size())
      throw std::logic_error("the " + backend.name() + " backend kept no '" + img.name +
                             "' pass of this frame");
  return out;
}

}  // namespace sdfreel
