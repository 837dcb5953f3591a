#pragma once
// A render folder's checkpoints of a shader's buffers (docs/shaders.md), handed to the backend:
// only for a shader with feedback and `[shader] checkpoint_every` above 0.
#include <string>

#include "pipeline/frame_pipeline.h"

namespace sdfreel {

// `render_key`: the manifest's (io/manifest_journal.h), so that a checkpoint of other settings is
// never used. `writable` false reads them only (verify).
void use_shader_checkpoints(FramePipeline& pipe, const std::string& out_dir,
                            const std::string& render_key, bool writable);

// The folder the checkpoints of `out_dir` are kept in.
std::string checkpoint_dir(const std::string& out_dir);

}  // namespace sdfreel
