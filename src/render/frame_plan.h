#pragma once
// A frame as a small plan of passes over named targets, run by both backends (CPU:
// backends/cpu/plan_runner, GL: backends/gl/gl_plan_runner).
//
// Targets are images, frame-sized unless they give a size: colour targets (RGBA float) and depth
// targets (window depth in channel 0, the convention of camera_model.h, cleared to 1). Every plan
// has three built-in targets: "colour" (the frame's output), "depth", and "sdf_evals" (x = SDF
// evaluations of the pixel's sample, for the bench; it used to ride in alpha).
//
// Setup passes run once per frame before the samples, into targets marked per_frame (cleared once,
// before them): what is the same for every sample, such as a light's shadow map drawn by a mesh
// pass with its own view. Later passes read such targets as inputs.
//
// Sub-pixel samples mean the same for every pass kind: the whole plan runs once per sample offset
// of FrameContext::sample_offsets (ray passes trace through pixel + offset, mesh passes use the
// projection moved by the same offset), and the frame is the sum of the samples' "colour" in list
// order times 1 / count. On GL the sum is a float add-blend of each sample into an accumulation
// target, one draw per sample in list order, so it adds the same numbers in the same order as the
// CPU loop.
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "render/image.h"
#include "render/mesh_fragments8.h"
#include "render/rays.h"
#include "render/shader_inputs.h"
#include "render/triangle_mesh.h"

namespace sdfreel {

constexpr const char* COLOUR_TARGET = "colour";
constexpr const char* DEPTH_TARGET = "depth";
constexpr const char* SDF_EVALS_TARGET = "sdf_evals";

enum class TargetKind { Colour, Depth };

struct TargetSpec {
  std::string name;
  TargetKind kind = TargetKind::Colour;
  glm::vec4 clear{0.0f};   // colour targets; depth targets clear to 1
  glm::ivec2 size{0};      // (0, 0): the frame's size
  bool per_frame = false;  // written by setup passes: cleared once a frame, not before each sample
};

enum class DepthTest { Off, TestAndWrite, TestOnly };  // LESS when on
enum class CullMode { None, Back, Front };             // front: counter-clockwise as seen

// What a ray pass's CPU code returns for up to eight rays. keep[i] false discards lane i (nothing
// written, as GLSL's discard); depth is window depth, read only when the pass has a depth target.
// The runner fills evals (the SDF evaluations each lane counted: RayStats::lane_evals).
struct RayPassOutput {
  glm::vec3 colour[LANES];
  float depth[LANES];
  bool keep[LANES];
  int32_t evals[LANES];

  // Before a pass: every lane discarded at depth 1, as GL's fragment stage starts a fragment.
  void start() {
    for (int i = 0; i < LANES; ++i) keep[i] = false, depth[i] = 1.0f;
  }
};

// A per-pixel function of a primary ray: what scenes were before plans. CPU: `packet` on packets
// of eight from the eye (and `scalar`, one ray, for SDFREEL_SIMD=0), bit-identical to each other.
// GL: `shader`, a fragment file that includes common/sample_loop.glsl ("" = SceneInfo::shader).
struct RayPass {
  std::string name;
  std::string colour = COLOUR_TARGET;
  std::string sdf_evals = SDF_EVALS_TARGET;  // "" = not counted
  std::string depth;                         // "" = no depth written or tested
  DepthTest depth_test = DepthTest::Off;
  std::string shader;
  std::vector<ShaderUniform> uniforms;
  std::function<void(const RayPacket&, RayPassOutput&, RayStats&)> packet;
  std::function<void(const Ray&, glm::vec3& colour, float& depth, bool& keep, RayStats&)> scalar;
  // Optional, for a pass whose every ray gives one colour, kept, counting no SDF evaluation (a
  // plain background): that colour. The CPU then fills the pass's targets without tracing, when the
  // pass has no depth (tests/passes/uniform_ray_pass_test.cpp: the same bits as tracing).
  std::optional<glm::vec3> uniform_colour;
};

// Instances of a triangle mesh: each draws the mesh with its model matrix; `data` is a free vec4
// per instance (colour, material id, shell index...), attribute 7 on GL.
struct MeshInstance {
  glm::mat4 model{1.0f};
  glm::vec4 data{0.0f};
};

// The images a pass reads, in the order of its inputs (ImagePass::inputs, MeshPass::inputs).
struct ImageInputs {
  std::vector<const ImageRGBA*> images;
  const ImageRGBA& operator[](size_t i) const { return *images[i]; }
};

// Varyings of a mesh pass's shading function, per covered sample.
struct MeshFragment {
  glm::vec3 world_position, world_normal;  // normal interpolated, not normalised
  glm::vec2 uv;
  glm::vec4 instance_data;
  bool front_facing;
  const ImageInputs* inputs = nullptr;  // the pass's inputs (MeshPass::inputs), in their order
};

// A vertex after a custom vertex stage: world position and (unnormalised) world normal.
struct PlacedVertex {
  glm::vec3 world, normal;
};

// A view of its own for a mesh pass that draws from elsewhere than the plan's camera (a light's
// shadow map): clip = projection * view * world, never moved by the sample offset, into targets of
// any size. GL: the pass's u_view and u_projection.
struct PassView {
  glm::mat4 view{1.0f}, projection{1.0f};
};

// An input of a pass: a target read through `sampler` with texelFetch on GL. Image passes read
// image rows top-down on both backends (their shaders flip); a mesh pass reading texel (x, y) as
// GL stores it (row 0 at the bottom) reads the CPU image's row height - 1 - y.
struct ImageInput {
  std::string target;
  std::string sampler;
};

// Triangles with depth test and write, cull mode and alpha discard (alpha < alpha_cutoff is
// discarded). CPU: `shade` per covered sample, and `place` per vertex when the pass has its own
// `vertex` shader (empty: world = model * position, normal = mat3(model) * normal, as
// common/mesh.vert). GL: `vertex` and `fragment` shader files. colour "" draws depth only (CPU:
// `shade` may then be empty).
struct MeshPass {
  std::string name;
  std::shared_ptr<const TriangleMesh> mesh;  // shared: backends cache their copy by this pointer
  std::vector<MeshInstance> instances{MeshInstance{}};
  std::string colour = COLOUR_TARGET;
  std::string depth = DEPTH_TARGET;
  DepthTest depth_test = DepthTest::TestAndWrite;
  CullMode cull = CullMode::Back;
  float alpha_cutoff = 0.0f;
  std::string vertex = "common/mesh.vert", fragment;
  std::vector<ShaderUniform> uniforms;
  std::vector<ImageInput> inputs;  // targets the shading reads (MeshFragment::inputs)
  std::optional<PassView> view;    // none: the plan's camera
  std::function<glm::vec4(const MeshFragment&)> shade;
  // Optional CPU fast path of `shade`, preferred when set: eight fragments of a triangle at once,
  // each lane with `shade`'s bits for that fragment (lane code: the same operations in the same
  // order).
  std::function<void(const MeshFragments8&, FragmentColours8&)> shade8;
  // Instead of `shade`, for surfaces found inside the mesh (ray marching in a bounding mesh): the
  // fragment's colour and its own window depth, or false to discard. The depth test and write use
  // that depth (a late test, as GL does when the fragment shader writes gl_FragDepth).
  std::function<bool(const MeshFragment&, glm::vec4& colour, float& depth)> shade_depth;
  std::function<PlacedVertex(const MeshInstance&, const glm::vec3& position,
                             const glm::vec3& normal)>
      place;
};

// A pixel function of other targets (post-processing, compositing): output(x, y) from the inputs,
// pixels independent of each other so threads never change bits. GL: a full-screen pass of
// `shader`, each input bound to its sampler (read with texelFetch), image row 0 at the top as on
// the CPU (the shader flips gl_FragCoord.y).
struct ImagePass {
  std::string name;
  std::vector<ImageInput> inputs;
  std::string output = COLOUR_TARGET;  // never one of the inputs
  std::string shader;
  std::vector<ShaderUniform> uniforms;
  std::function<glm::vec4(const ImageInputs&, int x, int y)> pixel;
  // Optional CPU fast path, preferred when set: called once per run with the inputs (to summarise
  // them), it returns a function that writes pixels x0 <= x < x1 of row y to `out` (4 floats a
  // pixel), giving `pixel`'s bits (lane code: the same operations in the same order).
  using RowFunction = std::function<void(int y, int x0, int x1, float* out)>;
  std::function<RowFunction(const ImageInputs&)> rows;
};

using Pass = std::variant<RayPass, MeshPass, ImagePass>;

struct FramePlan {
  std::vector<TargetSpec> targets;  // besides the built-in colour, depth and sdf_evals
  std::vector<Pass> setup_passes;   // run in order, once per frame, before the samples
  std::vector<Pass> passes;         // run in order, once per sample
  float near_plane = 0.05f, far_plane = 500.0f;
};

// The targets of `plan`: the built-ins, then the plan's own.
std::vector<TargetSpec> plan_targets(const FramePlan& plan);
const std::string& pass_name(const Pass& pass);

}  // namespace sdfreel
