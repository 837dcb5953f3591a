#include "scenes/museum/atmosphere.h"

#include <algorithm>

#include "render/camera.h"
#include "render/camera_lanes.h"
#include "render/passes/crepuscular_rays.h"
#include "scenes/museum/lighting.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"

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
  p.rows = [](const ImageInputs& in) {
    return [&depth = in[0]](int y, int x0, int x1, float* out) {
      for (int x = x0; x < x1; ++x, out += 4) {
        out[0] = out[1] = out[2] = depth.at(x, y)[0] >= 1.0f ? 1.0f : 0.0f;
        out[3] = 1.0f;
      }
    };
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

// composite() for eight pixels of row y from x on (lanes past the row's end `n` repeat its last
// pixel): each lane does composite()'s operations in its order (primary_ray_dir's included).
void composite_packet(const CompositeFrame& f, const ImageInputs& in, int y, int x, int n,
                      float* out) {
  F8 px, z, rays;
  V3x8 hall;
  for (int i = 0; i < LANES; ++i) {
    const int xi = x + (i < n ? i : n - 1);
    const float* h = in[0].at(xi, y);
    hall.set_lane(i, vec3(h[0], h[1], h[2]));
    rays[i] = in[1].at(xi, y)[0];
    z[i] = in[2].at(xi, y)[0];
    px[i] = float(xi) + 0.5f;
  }
  const F8 view = f.model.near_plane / (1.0f - z / f.model.depth_scale);
  const F8 d = select(z >= 1.0f, splat(FOG_MAX_DISTANCE), dm::min(view, FOG_MAX_DISTANCE));
  const F8 s = f.air.fog_density * d;
  const F8 fog = 1.0f - 1.0f / (1.0f + s + 0.5f * s * s);
  const V3x8 dir = primary_ray_dirs(f.camera, px, splat(float(y) + 0.5f), f.width, f.height);
  F8 lobe = dm::max(vdot(dir, TO_SUN), 0.0f);
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  const V3x8 fog_colour = FOG_AMBIENT + FOG_SUN * lobe;
  const V3x8 c =
      hall * (1.0f - fog) + fog_colour * fog + SHAFT_COLOUR * (rays * f.air.rays_strength);
  for (int i = 0; i < n; ++i, out += 4) {
    out[0] = c.x[i];
    out[1] = c.y[i];
    out[2] = c.z[i];
    out[3] = 1.0f;
  }
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
  p.rows = [f](const ImageInputs& in) {
    return [f, &in](int y, int x0, int x1, float* out) {
      for (int x = x0; x < x1; x += LANES)
        composite_packet(f, in, y, x, x1 - x < LANES ? x1 - x : LANES, out + 4 * (x - x0));
    };
  };
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
  p.rows = [](const ImageInputs& in) {
    return [&from = in[0]](int y, int x0, int x1, float* out) {
      std::copy(from.at(x0, y), from.at(x0, y) + 4 * (x1 - x0), out);
    };
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
