#include "render/frame_context.h"

#include "render/sample_pattern.h"

namespace sdfreel {

void finish_frame_context(FrameContext& ctx) {
  ctx.march = march_settings(ctx.quality);
  ctx.camera = make_camera_basis(ctx.pose);
  ctx.sample_offsets = sample_offsets(ctx.adaptive.enabled ? ctx.adaptive.maximum : ctx.samples);
}

AdaptiveSampling sampling_of(const FrameContext& ctx) {
  if (ctx.adaptive.enabled) return ctx.adaptive;
  const int n = int(ctx.sample_offsets.size());
  return AdaptiveSampling{false, n, n, 0.0f};
}

}  // namespace sdfreel
