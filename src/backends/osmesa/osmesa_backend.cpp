#include "backends/osmesa/osmesa_backend.h"

#include <stdexcept>

#include "backends/osmesa/frame_uniforms.h"
#include "backends/osmesa/shader_dir.h"

namespace sdfreel {

namespace {

// "4.5 (Core Profile) Mesa 22.3.6" -> "22.3.6".
std::string mesa_version(const std::string& gl_version) {
  const size_t at = gl_version.find("Mesa ");
  if (at == std::string::npos) return "unknown";
  const size_t start = at + 5;
  const size_t end = gl_version.find(' ', start);
  return gl_version.substr(start, end == std::string::npos ? end : end - start);
}

}  // namespace

OsmesaBackend::OsmesaBackend() : platform_(std::make_unique<OsmesaPlatform>()) {
  driver_ = std::make_unique<GlDriver>(*platform_, find_shader_dir());
}

OsmesaBackend::~OsmesaBackend() {
  try {
    platform_->make_current();  // the driver deletes its GL objects in this context
    runner_.reset();
    driver_.reset();
  } catch (const GlPlatformError&) {
    runner_.release();
    driver_.release();  // no context to delete them in: destroying the context frees them
  }
}

std::map<std::string, std::string> OsmesaBackend::versions() const {
  platform_->make_current();
  const GlApi& gl = platform_->gl();
  const std::string version = gl.string(GL_VERSION);
  return {{"mesa", mesa_version(version)},
          {"gl_version", version},
          {"gl_renderer", gl.string(GL_RENDERER)}};
}

void OsmesaBackend::begin(const SceneInfo& scene) {
  scene_ = scene.make ? scene.make() : nullptr;
  if (!scene_) throw std::runtime_error("scene '" + scene.name + "' has no C++ implementation");
  if (scene.shader.empty())
    throw std::runtime_error("scene '" + scene.name +
                             "' has no GLSL shader for the osmesa backend");
  scene_shader_ = scene.shader;
  textures_.clear();
  textures_key_ = 0;
  platform_->make_current();
  runner_ = std::make_unique<GlPlanRunner>(*driver_);
  runner_->program("common/fullscreen.vert", scene.shader);  // compile errors before any frame
  // llvmpipe compiles the shader to machine code at its first draw, which takes seconds for a
  // large scene: draw one pixel now, so that frame times (manifest, bench) measure rendering.
  FrameContext warm_up;
  warm_up.width = warm_up.height = 1;
  warm_up.pose = scene.default_camera;
  warm_up.params = ParamValues(&scene.params);
  finish_frame_context(warm_up);
  RayStats ignored;
  render(warm_up, ignored);
}

ImageRGBA OsmesaBackend::render(const FrameContext& ctx, RayStats& stats) {
  if (!scene_) throw std::logic_error("OsmesaBackend::render before begin");
  platform_->make_current();
  scene_->prepare(ctx);
  GlSceneInputs inputs{scene_shader_, scene_->shader_uniforms(), {}};
  // Upload the textures when their content changes, not every frame (27 MB for the lanterns).
  const uint64_t key = scene_->shader_textures_key();
  if (key == 0 || key != textures_key_) {
    textures_.clear();
    for (const ShaderTexture& t : scene_->shader_textures())
      textures_.push_back({t.name, driver_->upload_texture(t)});
    textures_key_ = key;
  }
  inputs.textures = textures_;
  return runner_->run(scene_->frame_plan(ctx), ctx, inputs, stats, &counts_);
}

}  // namespace sdfreel
