#pragma once
// What one GL pass draws, where, and with which inputs. A ray-marched scene is a single
// full-screen pass; fur shells (a mesh drawn once per shell with instancing, depth-tested),
// crepuscular rays (an occlusion pass into an off-screen target, then a radial blur reading it)
// and other multi-pass scenes are lists of these.
#include <array>
#include <string>
#include <vector>

#include "backends/gl/gl_platform.h"
#include "render/triangle_mesh.h"
#include "scenes/scene.h"

namespace sdfreel {

using GlProgramId = int;  // from GlDriver::compile
using GlMeshId = int;     // from GlDriver::create_mesh
constexpr GlMeshId FULL_SCREEN_TRIANGLE = -1;

// LESS test when on; Always writes depth without testing (a ray pass that lays down depth).
enum class DepthMode { Off, TestAndWrite, TestOnly, Always };
enum class GlCull { None, Back, Front };  // front faces are counter-clockwise in window space
enum class BlendMode { Replace, Add, PremultipliedOver };

// A sampler uniform and the GL texture it reads: a scene texture (GlDriver::texture) or a colour
// attachment of an earlier pass's render target.
struct GlTextureBinding {
  std::string sampler;
  GLuint texture = 0;
};

struct GlPass {
  std::string name;  // for error messages
  GlProgramId program = -1;
  GlTargetRef target;  // the platform's frame target or a GlRenderTarget
  GlMeshId mesh = FULL_SCREEN_TRIANGLE;
  int instances = 1;  // gl_InstanceID runs 0..instances-1
  bool clear = true;  // clear colour (and depth, if the target has it) first
  std::array<float, 4> clear_color{0.0f, 0.0f, 0.0f, 0.0f};
  DepthMode depth = DepthMode::Off;
  GlCull cull = GlCull::None;
  BlendMode blend = BlendMode::Replace;
  // Draws only into window rows [first, first + count) when count > 0 (the clear is not limited).
  int scissor_first_row = 0, scissor_rows = 0;
  // Every active non-sampler uniform of the program must be given a value: an unset uniform
  // would silently read 0, the classic way for two backends to drift apart.
  std::vector<ShaderUniform> uniforms;
  std::vector<GlTextureBinding> textures;
};

// Triangle mesh: attribute 0 position (vec3), 1 normal (vec3), 2 uv (vec2). Normals and uvs may
// be empty; indices may be empty (then vertices are drawn in order, three per triangle). Per
// instance (GlDriver::set_instances): attributes 3..6 the model matrix's columns, 7 a free vec4.
using GlMesh = TriangleMesh;

}  // namespace sdfreel
