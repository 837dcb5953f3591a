#include "backends/gl/gl_backend.h"

#include <stdexcept>

#include "backends/gl/frame_uniforms.h"
#include "backends/gl/shader_dir.h"
#include "render/tiling.h"
#include "shader/shader_hash.h"

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

GlBackend::GlBackend(const GlChoice& choice)
    : platform_(make_gl_platform(choice)), threads_(choice.threads) {
  driver_ = std::make_unique<GlDriver>(*platform_, find_shader_dir());
  platform_->release();  // the thread that renders makes it current (EGL: one thread at a time)
}

GlBackend::~GlBackend() {
  try {
    platform_->make_current();  // the driver deletes its GL objects in this context
    shadertoy_.reset();
    runner_.reset();
    driver_.reset();
    platform_->release();
  } catch (const GlPlatformError&) {
    shadertoy_.release();
    runner_.release();
    driver_.release();  // no context to delete them in: destroying the context frees them
  }
}

std::map<std::string, std::string> GlBackend::versions() const {
  platform_->make_current();
  const GlApi& gl = platform_->gl();
  const std::string version = gl.string(GL_VERSION);
  std::map<std::string, std::string> v = {{"platform", platform_->name()},
                                          {"device", platform_->device()},
                                          {"mesa", mesa_version(version)},
                                          {"gl_version", version},
                                          {"gl_renderer", gl.string(GL_RENDERER)}};
  platform_->release();
  if (project_) v["shader_sha256"] = shader_project_sha256(*project_);  // the user's code and files
  return v;
}

void GlBackend::set_frame_source(std::function<FrameContext(int)> source) {
  frame_source_ = source;
  if (shadertoy_) shadertoy_->set_frame_source(std::move(source));
}

void GlBackend::set_checkpoints(std::shared_ptr<BufferCheckpoints> checkpoints) {
  checkpoints_ = checkpoints;
  if (shadertoy_) shadertoy_->set_checkpoints(std::move(checkpoints));
}

void GlBackend::begin_shader(const SceneInfo& scene) {
  project_ = scene.shader_project;
  scene_.reset();
  platform_->make_current();
  shadertoy_.reset();
  shadertoy_ = std::make_unique<ShadertoyRunner>(platform_->gl(), find_shader_dir(), project_);
  shadertoy_->set_frame_source(frame_source_);
  shadertoy_->set_checkpoints(checkpoints_);
  platform_->release();
}

void GlBackend::begin(const SceneInfo& scene) {
  if (scene.shader_project) return begin_shader(scene);
  shadertoy_.reset();
  project_.reset();
  scene_ = scene.make ? scene.make() : nullptr;
  if (!scene_) throw std::runtime_error("scene '" + scene.name + "' has no C++ implementation");
  if (scene.shader.empty())
    throw std::runtime_error("scene '" + scene.name + "' has no GLSL shader for the GL backend");
  scene_shader_ = scene.shader;
  textures_.clear();
  textures_key_ = 0;
  platform_->make_current();
  runner_ = std::make_unique<GlPlanRunner>(*driver_, threads_);
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

ImageRGBA GlBackend::render(const FrameContext& ctx, RayStats& stats) {
  if (shadertoy_) {
    platform_->make_current();
    ImageRGBA image = shadertoy_->render(ctx);
    platform_->release();
    counts_.assign(size_t(ctx.width) * size_t(ctx.height), uint16_t(ctx.sample_offsets.size()));
    return image;
  }
  if (!scene_) throw std::logic_error("GlBackend::render before begin");
  platform_->make_current();
  with_threads(threads_, [&] { scene_->prepare(ctx); });
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
  ImageRGBA image = runner_->run(scene_->frame_plan(ctx), ctx, inputs, stats, &counts_,
                                 record_evals_ ? &evals_ : nullptr);
  platform_->release();  // the next frame may come from another thread
  return image;
}

}  // namespace sdfreel
