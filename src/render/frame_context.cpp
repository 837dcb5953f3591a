#include "render/frame_context.h"

#include "render/sample_pattern.h"

namespace sdfreel {

void finish_frame_context(FrameContext& ctx) {
  ctx.march = march_settings(ctx.quality);
  ctx.camera = make_camera_basis(ctx.pose);
  ctx.sample_offsets = sample_offsets(ctx.samples);
}

}  // namespace sdfreel
