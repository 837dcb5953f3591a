#pragma once
// One measured case: a scene's own mesh passes at one frame size and sample count, taken from the
// scene's public frame plan (so the comparison follows whatever the renderer draws), and the same
// triangles flattened to world space for the methods that need them.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/camera_model.h"
#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "scenes/scene.h"

namespace sdfreel::mesh_bench {

struct CaseSpec {
  std::string name;        // "hall", "fur", "museum"
  std::string scene;       // registry name
  double time = 2.0;       // TIME
  bool hall_only = false;  // only the pass named "hall"
};

// The cases the README quotes: the museum's hall, the fur case close up (the fur scene), and every
// mesh pass of the museum's default view (hall and the fur case on its plinth).
std::vector<CaseSpec> standard_cases();

struct BenchCase {
  std::string name;
  FrameContext ctx;
  CameraModel camera;
  std::unique_ptr<Scene> scene;     // owns what the passes' functions may point at
  std::vector<MeshPass> passes;     // the plan's mesh passes with CPU shading, in plan order
  std::vector<TargetSpec> targets;  // the plan's targets (the passes draw into them)
};

BenchCase make_case(const CaseSpec& spec, int width, int height, int samples);

// Every triangle of every pass and instance after the vertex stage (the pass's `place`, or the
// instance's model matrix), in the order the rasteriser draws them: pass, instance, triangle. A
// triangle's index here is its id everywhere in this tool.
struct FlatTriangles {
  std::vector<glm::vec3> world;  // three per triangle
  std::vector<glm::vec2> uv;     // three per triangle
  std::vector<uint32_t> pass_of, instance_of;
  std::vector<uint32_t> first_of_pass;  // id of each pass's first triangle, plus the total
  size_t count() const { return pass_of.size(); }
};

FlatTriangles flatten(const BenchCase& c);

}  // namespace sdfreel::mesh_bench
