#include "pipeline/shader_checkpoints.h"

#include <memory>

#include "io/checkpoint_folder.h"
#include "shader/shader_project.h"

namespace sdfreel {

std::string checkpoint_dir(const std::string& out_dir) {
  return out_dir + "/checkpoints";
}

void use_shader_checkpoints(FramePipeline& pipe, const std::string& out_dir,
                            const std::string& render_key, bool writable) {
  const ShaderProject* project = pipe.scene().shader_project.get();
  if (!project || !project->has_feedback() || project->checkpoint_every <= 0) return;
  pipe.backend().set_checkpoints(std::make_shared<CheckpointFolder>(
      checkpoint_dir(out_dir), render_key, project->checkpoint_every, pipe.timeline().frame_count(),
      writable));
}

}  // namespace sdfreel
