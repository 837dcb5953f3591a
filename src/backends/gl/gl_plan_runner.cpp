#include "backends/gl/gl_plan_runner.h"

#include <stdexcept>

#include "backends/gl/frame_uniforms.h"
#include "backends/gl/live_pixel_packing.h"
#include "render/camera_model.h"

namespace sdfreel {

namespace {

constexpr const char* FULL_SCREEN_VERTEX = "common/fullscreen.vert";
constexpr const char* SUM_COLOUR = "sum.colour";  // not names a plan can declare: they have a dot
constexpr const char* SUM_EVALS = "sum.sdf_evals";
constexpr const char* SUM_ODD = "sum.odd";
constexpr const char* LIVE_MASK = "u_live_mask";
constexpr const char* LIVE_PIXELS = "u_live_pixels";
constexpr const char* LIVE_SLOTS = "u_live_slots";

ShaderUniform matrix(const std::string& name, const glm::mat4& m) {
  ShaderUniform u{name, 16, {}};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) u.values.push_back(m[c][r]);
  return u;
}

// The frame's uniforms for one sample: its offset alone (sample loops run once), the camera model
// with the projection moved by that offset.
std::vector<ShaderUniform> sample_uniforms(const FrameContext& ctx, const CameraModel& cam,
                                           glm::vec2 offset) {
  std::vector<ShaderUniform> u = frame_uniforms(ctx);
  for (ShaderUniform& v : u) {
    if (v.name == "u_sample_offsets") v.values = {offset.x, offset.y};
    if (v.name == "u_sample_count" || v.name == "u_inv_samples") v.values = {1.0f};
  }
  u.push_back({"u_sample_offset", 2, {offset.x, offset.y}});
  u.push_back(matrix("u_view", cam.view));
  u.push_back(matrix("u_projection", sample_projection(cam, offset, ctx.width, ctx.height)));
  u.push_back({"u_near_plane", 1, {cam.near_plane}});
  u.push_back({"u_depth_scale", 1, {cam.depth_scale}});
  return u;
}

DepthMode depth_mode(const std::string& target, DepthTest test) {
  if (target.empty()) return DepthMode::Off;
  if (test == DepthTest::Off) return DepthMode::Always;
  return test == DepthTest::TestOnly ? DepthMode::TestOnly : DepthMode::TestAndWrite;
}

GlCull gl_cull(CullMode c) {
  return c == CullMode::None ? GlCull::None : c == CullMode::Back ? GlCull::Back : GlCull::Front;
}

void append(std::vector<ShaderUniform>& to, const std::vector<ShaderUniform>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

// A pass with a view of its own draws with it instead of the camera's.
void use_view(std::vector<ShaderUniform>& uniforms, const PassView& view) {
  for (ShaderUniform& u : uniforms) {
    if (u.name == "u_view") u = matrix("u_view", view.view);
    if (u.name == "u_projection") u = matrix("u_projection", view.projection);
  }
}

}  // namespace

GlProgramId GlPlanRunner::program(const std::string& vertex, const std::string& fragment) {
  const std::string key = vertex + "|" + fragment;
  const auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  const GlProgramId id = driver_.compile({vertex, fragment, ""});
  programs_[key] = id;
  return id;
}

GlMeshId GlPlanRunner::mesh(const std::shared_ptr<const TriangleMesh>& m) {
  if (!m) throw std::runtime_error("a mesh pass has no mesh");
  const auto it = meshes_.find(m);
  if (it != meshes_.end()) return it->second;
  return meshes_[m] = driver_.create_mesh(*m);
}

void GlPlanRunner::run_pass(const Pass& pass, const GlSceneInputs& scene,
                            const std::vector<ShaderUniform>& base, int packed_rows) {
  GlPass p;
  p.scissor_rows = packed_rows;
  p.name = pass_name(pass);
  p.clear = false;
  p.uniforms = base;
  if (const auto* ray = std::get_if<RayPass>(&pass)) {
    const std::string& shader = ray->shader.empty() ? scene.shader : ray->shader;
    p.program = program(FULL_SCREEN_VERTEX, shader);
    std::vector<std::string> outputs = {ray->colour};
    if (!ray->sdf_evals.empty()) outputs.push_back(ray->sdf_evals);
    p.target = targets_.framebuffer(outputs, ray->depth, p.name);
    p.depth = depth_mode(ray->depth, ray->depth_test);
    append(p.uniforms, scene.uniforms);
    append(p.uniforms, ray->uniforms);
    p.textures = scene.textures;
    p.textures.push_back({LIVE_MASK, live_mask_});
    p.textures.push_back({LIVE_PIXELS, live_pixels_});
  } else if (const auto* m = std::get_if<MeshPass>(&pass)) {
    p.program = program(m->vertex, m->fragment);
    p.mesh = mesh(m->mesh);
    if (m->view) use_view(p.uniforms, *m->view);
    std::vector<float> instances;
    for (const MeshInstance& i : m->instances) {
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) instances.push_back(i.model[c][r]);
      instances.insert(instances.end(), {i.data.x, i.data.y, i.data.z, i.data.w});
    }
    driver_.set_instances(p.mesh, instances);
    p.instances = int(m->instances.size());
    std::vector<std::string> colours;
    if (!m->colour.empty()) colours.push_back(m->colour);
    p.target = targets_.framebuffer(colours, m->depth, p.name);
    p.depth = depth_mode(m->depth, m->depth_test);
    p.cull = gl_cull(m->cull);
    p.uniforms.push_back({"u_alpha_cutoff", 1, {m->alpha_cutoff}});
    append(p.uniforms, scene.uniforms);
    append(p.uniforms, m->uniforms);
    p.textures = scene.textures;
    for (const ImageInput& in : m->inputs) {
      if (in.target == m->colour || in.target == m->depth)
        throw std::runtime_error("mesh pass '" + m->name + "' reads its own target '" + in.target +
                                 "'");
      p.textures.push_back({in.sampler, targets_.texture(in.target, m->name)});
    }
  } else {
    const ImagePass& img = std::get<ImagePass>(pass);
    p.program = program(FULL_SCREEN_VERTEX, img.shader);
    for (const ImageInput& in : img.inputs) {
      if (in.target == img.output)
        throw std::runtime_error("image pass '" + img.name + "' reads its own output '" +
                                 img.output + "'");
      p.textures.push_back({in.sampler, targets_.texture(in.target, img.name)});
    }
    p.target = targets_.framebuffer({img.output}, "", p.name);
    append(p.uniforms, img.uniforms);
  }
  driver_.run(p);
}

void GlPlanRunner::accumulate(bool odd, bool packed) {
  GlPass p;
  p.name = "accumulate samples";
  p.program = program(FULL_SCREEN_VERTEX, "common/accumulate.glsl");
  p.target = targets_.framebuffer({SUM_COLOUR, SUM_EVALS, SUM_ODD}, "", p.name);
  p.clear = false;
  p.blend = BlendMode::Add;
  p.uniforms = {{"u_odd", 1, {odd ? 1.0f : 0.0f}}, {"u_packed", 1, {packed ? 1.0f : 0.0f}}};
  p.textures = {{"u_colour", targets_.texture(COLOUR_TARGET, p.name)},
                {"u_sdf_evals", targets_.texture(SDF_EVALS_TARGET, p.name)},
                {LIVE_MASK, live_mask_},
                {LIVE_SLOTS, live_slots_}};
  driver_.run(p);
}

// The mask as a one-channel float texture in GL's row order (row 0 at the bottom), so shaders
// read it at gl_FragCoord.
void GlPlanRunner::upload_live_mask(const std::vector<uint8_t>& live, int width, int height) {
  ShaderTexture t{LIVE_MASK, width, height, 1, std::vector<float>(live.size())};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      t.texels[size_t(y) * width + x] = float(live[size_t(height - 1 - y) * width + x]);
  live_mask_ = driver_.upload_texture(t);
}

void GlPlanRunner::upload_packing(const std::vector<uint8_t>& live, int width, int height) {
  const LivePixelPacking p = pack_live_pixels(live, width, height, LIVE_PIXELS, LIVE_SLOTS);
  live_pixels_ = driver_.upload_texture(p.pixels);
  live_slots_ = driver_.upload_texture(p.slots);
  packed_rows_ = p.rows;
}

ImageRGBA GlPlanRunner::run(const FramePlan& plan, const FrameContext& ctx,
                            const GlSceneInputs& scene, RayStats& stats, SampleCounts* counts,
                            std::vector<float>* evals_out) {
  std::vector<TargetSpec> specs = plan_targets(plan);
  const size_t plan_target_count = specs.size();
  for (const char* sum : {SUM_COLOUR, SUM_EVALS, SUM_ODD})
    specs.push_back({sum, TargetKind::Colour, glm::vec4(0.0f)});
  targets_.prepare(specs, ctx.width, ctx.height);
  const CameraModel cam =
      make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane);
  for (const char* sum : {SUM_COLOUR, SUM_EVALS, SUM_ODD}) targets_.clear(sum);
  LivePixels live(sampling_of(ctx), ctx.width, ctx.height, threads_);
  if (!live_mask_full_ || live_mask_size_ != glm::ivec2(ctx.width, ctx.height)) {
    upload_live_mask(live.mask(), ctx.width, ctx.height);
    live_mask_full_ = true;
    live_mask_size_ = glm::ivec2(ctx.width, ctx.height);
  }
  // Only a plan of one ray pass may skip stopped pixels: other passes may read any pixel.
  const bool one_ray_pass = plan.passes.size() == 1 && plan.setup_passes.empty() &&
                            std::holds_alternative<RayPass>(plan.passes[0]);
  // It may also move them, packed, when it lays down no depth and its shader can (sample_loop).
  bool packable = false;
  if (one_ray_pass) {
    const RayPass& ray = std::get<RayPass>(plan.passes[0]);
    const GlProgramId id =
        program(FULL_SCREEN_VERTEX, ray.shader.empty() ? scene.shader : ray.shader);
    packable = ray.depth.empty() && driver_.program(id).uniforms.count("u_packed") != 0;
  }
  // Bound in every round (programs read all their samplers); used only in packed rounds.
  if (!live_pixels_) upload_packing(std::vector<uint8_t>(1, 0), 1, 1);
  bool packed = false;
  // Setup passes once, at pixel centres, into the per-frame targets (cleared once here).
  for (size_t k = 0; k < plan_target_count; ++k)
    if (specs[k].per_frame) targets_.clear(specs[k].name);
  if (!plan.setup_passes.empty()) {
    std::vector<ShaderUniform> base = sample_uniforms(ctx, cam, glm::vec2(0.5f));
    base.push_back({"u_discard_stopped", 1, {0.0f}});
    base.push_back({"u_packed", 1, {0.0f}});
    for (const Pass& pass : plan.setup_passes) run_pass(pass, scene, base, 0);
  }
  for (int i = 0; i < int(ctx.sample_offsets.size()); ++i) {
    if (live.round_ends_at(i)) {
      const ImageRGBA sum = driver_.read_rgba(targets_.framebuffer({SUM_COLOUR}, "", "round"));
      const ImageRGBA odd = driver_.read_rgba(targets_.framebuffer({SUM_ODD}, "", "round"));
      if (live.decide(i, sum, odd) == 0) break;
      upload_live_mask(live.mask(), ctx.width, ctx.height);
      live_mask_full_ = false;
      packed = packable;
      if (packed) upload_packing(live.mask(), ctx.width, ctx.height);
    }
    for (size_t k = 0; k < plan_target_count; ++k)
      if (!specs[k].per_frame) targets_.clear(specs[k].name);
    std::vector<ShaderUniform> base = sample_uniforms(ctx, cam, ctx.sample_offsets[size_t(i)]);
    base.push_back({"u_discard_stopped", 1, {one_ray_pass ? 1.0f : 0.0f}});
    base.push_back({"u_packed", 1, {packed ? 1.0f : 0.0f}});
    for (const Pass& pass : plan.passes) run_pass(pass, scene, base, packed ? packed_rows_ : 0);
    accumulate(i & 1, packed);
  }
  ImageRGBA img = driver_.read_rgba(targets_.framebuffer({SUM_COLOUR}, "", "read back"));
  const ImageRGBA evals = driver_.read_rgba(targets_.framebuffer({SUM_EVALS}, "", "read back"));
  // Times 1 / count as on the CPU; alpha is coverage, 1. Evaluation counts are exact integers in
  // float (below 2^24 a pixel).
  normalise_sums(img, live.counts(), threads_);
  for (size_t i = 0; i < evals.pixels.size(); i += 4) stats.sdf_evals += uint64_t(evals.pixels[i]);
  if (evals_out) {
    evals_out->resize(evals.pixels.size() / 4);
    for (size_t i = 0; i < evals_out->size(); ++i) (*evals_out)[i] = evals.pixels[i * 4];
  }
  if (counts) *counts = live.counts();
  return img;
}

}  // namespace sdfreel
