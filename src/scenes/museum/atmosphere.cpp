#include "scenes/museum/atmosphere.h"

#include "render/camera.h"
#include "render/passes/crepuscular_rays.h"
#include "scenes/museum/lighting.h"
#include "sdf/det_math.h"

namespace sdfreel::museum {
namespace {

using glm::vec3;

constexpr const char* OCCLUSION = "occlusion";
constexpr const char* RAYS = "rays";
const vec3 FOG_AMBIENT(0.10f, 0.105f, 0.11f);
const vec3 FOG_SUN(0.9f, 0.8f, 0.65f);
const vec3 SHAFT_COLOUR(1.0f, 0.9f, 0.75f);
constexpr float FOG_MAX_DISTANCE = 16.0f;  // the sky through the window: fog up to the wall

ImagePass occlusion_pass() {
  ImagePass p;
  p.name = "occlusion";
  p.inputs = {{DEPTH_TARGET, "u_depth"}};
  p.output = OCCLUSION;
  p.shader = "museum/occlusion.glsl";
  p.pixel = [](const ImageInputs& in, int x, int y) {
    const float v = in[0].at(x, y)[0] >= 1.0f ? 1.0f : 0.0f;
    return glm::vec4(v, v, v, 1.0f);
  };
  return p;
}

struct CompositeFrame {
  CameraBasis camera;
  CameraModel model;
  int width, height;
  Atmosphere air;
};

glm::vec4 composite(const CompositeFrame& f, const ImageInputs& in, int x, int y) {
  const float* hall = in[0].at(x, y);
  const float rays = in[1].at(x, y)[0];
  const float z = in[2].at(x, y)[0];
  const float d = z >= 1.0f ? FOG_MAX_DISTANCE : dm::min(view_depth(f.model, z), FOG_MAX_DISTANCE);
  const float s = f.air.fog_density * d;
  const float fog = 1.0f - 1.0f / (1.0f + s + 0.5f * s * s);
  const vec3 dir = primary_ray_dir(f.camera, float(x) + 0.5f, float(y) + 0.5f, f.width, f.height);
  float lobe = dm::max(glm::dot(dir, TO_SUN), 0.0f);
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  const vec3 fog_colour = FOG_AMBIENT + FOG_SUN * lobe;
  const vec3 c = vec3(hall[0], hall[1], hall[2]) * (1.0f - fog) + fog_colour * fog +
                 SHAFT_COLOUR * (rays * f.air.rays_strength);
  return glm::vec4(c, 1.0f);
}

ImagePass composite_pass(const CompositeFrame& f, const std::string& scene) {
  ImagePass p;
  p.name = "composite";
  p.inputs = {{scene, "u_scene"}, {RAYS, "u_rays_image"}, {DEPTH_TARGET, "u_depth"}};
  p.output = COLOUR_TARGET;
  p.shader = "museum/composite.glsl";
  p.uniforms = {{"u_fog_density", 1, {f.air.fog_density}},
                {"u_rays_strength", 1, {f.air.rays_strength}}};
  p.pixel = [f](const ImageInputs& in, int x, int y) { return composite(f, in, x, y); };
  return p;
}

}  // namespace

ImagePass copy_pass(const std::string& from, const std::string& to) {
  ImagePass p;
  p.name = "copy " + from;
  p.inputs = {{from, "u_source"}};
  p.output = to;
  p.shader = "museum/copy.glsl";
  p.pixel = [](const ImageInputs& in, int x, int y) {
    const float* v = in[0].at(x, y);
    return glm::vec4(v[0], v[1], v[2], v[3]);
  };
  return p;
}

void add_atmosphere_passes(FramePlan& plan, const Atmosphere& a, const FrameContext& ctx,
                           const CameraModel& cam, const std::string& scene) {
  plan.targets.push_back({OCCLUSION, TargetKind::Colour, glm::vec4(0.0f)});
  plan.targets.push_back({RAYS, TargetKind::Colour, glm::vec4(0.0f)});
  plan.passes.push_back(occlusion_pass());
  CrepuscularRays rays;
  crepuscular_light(rays, cam, TO_SUN);
  plan.passes.push_back(crepuscular_rays_pass(rays, OCCLUSION, RAYS));
  plan.passes.push_back(composite_pass({ctx.camera, cam, ctx.width, ctx.height, a}, scene));
}

}  // namespace sdfreel::museum
