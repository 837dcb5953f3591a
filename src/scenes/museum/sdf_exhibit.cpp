#include "scenes/museum/sdf_exhibit.h"

#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "render/quality.h"
#include "scenes/common/surface_output.h"
#include "scenes/museum/meshes.h"
#include "scenes/museum/sun_shadow.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/march.h"
#include "scenes/sdf_morph/render.h"
#include "sdf/det_math.h"

namespace sdfreel::museum {
namespace {

using glm::vec3;

constexpr float MIN_EPS = 1e-4f;  // object units
constexpr float NORMAL_EPS = 1e-3f;
const vec3 BOUND_HALF(sdf_morph::OBJECT_BOUND_RADIUS);  // the box around the bounding sphere

// Everything a fragment of the exhibit needs, fixed for the frame.
struct ExhibitFrame {
  glm::mat4 inv_model;  // world -> sdf_morph object space (its pedestal top at PEDESTAL_HEIGHT)
  glm::mat3 to_world;   // object directions -> world, unit scale
  float scale;          // world metres per object unit
  sdf_morph::MorphUniforms morph;
  HallLight light;
  std::shared_ptr<const ReflectionProbe> probe;
  vec3 eye, forward;
  float pixel_angle, near_plane, depth_scale;
};

// (t_enter, t_exit) of ray o + d t with the box |p - c| <= BOUND_HALF.
glm::vec2 box_span(const vec3& o, const vec3& d) {
  const vec3 c = sdf_morph::objectBoundCenter();
  float t0 = -1e30f, t1 = 1e30f;
  for (int k = 0; k < 3; ++k) {
    const float inv = 1.0f / d[k];
    const float a = (c[k] - BOUND_HALF[k] - o[k]) * inv, b = (c[k] + BOUND_HALF[k] - o[k]) * inv;
    t0 = dm::max(t0, dm::min(a, b));
    t1 = dm::min(t1, dm::max(a, b));
  }
  return {t0, t1};
}

vec3 object_normal(const vec3& p, const sdf_morph::MorphUniforms& u) {
  const vec3 a(1.0f, -1.0f, -1.0f), b(-1.0f, -1.0f, 1.0f), c(-1.0f, 1.0f, -1.0f), d(1.0f);
  const float e = NORMAL_EPS;
  const vec3 g = a * sdf_morph::mapObject(p + a * e, u) + b * sdf_morph::mapObject(p + b * e, u) +
                 c * sdf_morph::mapObject(p + c * e, u) + d * sdf_morph::mapObject(p + d * e, u);
  return g / dm::sqrt(glm::dot(g, g));
}

// The hit threshold at path length t (object units): the quality preset's, in pixel footprints.
float hit_eps(const ExhibitFrame& f, float t) {
  return f.morph.naive ? f.morph.hit_eps : dm::max(MIN_EPS, f.morph.hit_eps * f.pixel_angle * t);
}

// What the mirror at p (normal n, reflected direction r, object space; t_hit the path so far)
// sees: the object itself (the mug's inside, the torus's far side) marched as sdf_morph's
// reflection is, shaded unshadowed and mirroring the probe, or else the hall through the probe.
vec3 exhibit_reflection(const ExhibitFrame& f, const vec3& p, const vec3& n, const vec3& r,
                        float t_hit) {
  const vec3 ro = p + n * sdf_morph::surfaceBias(hit_eps(f, t_hit));
  const glm::vec2 span = box_span(ro, r);
  float t = dm::max(span.x, 0.0f);
  for (int i = 0; i < f.morph.reflect_steps && t < span.y; ++i) {
    const float d = sdf_morph::mapObject(ro + r * t, f.morph);
    if (d < hit_eps(f, t_hit + t)) {
      const vec3 nq = object_normal(ro + r * t, f.morph);
      const vec3 mirror = sample_probe(*f.probe, f.to_world * sdf_morph::reflectDir(r, nq));
      return sdf_morph::shadeObjectLit(nq, r, mirror, 1.0f, 1.0f, f.morph);
    }
    t = t + d;
  }
  return sample_probe(*f.probe, f.to_world * r);
}

// The camera's ray through a point of the bound's back face, marched in object space with plain
// sphere tracing (the morph is 1-Lipschitz) and the quality preset's steps and threshold (in pixel
// footprints).
bool shade_exhibit(const ExhibitFrame& f, const vec3& world_point, const ImageRGBA& sun_map,
                   glm::vec4& colour, float& depth) {
  const vec3 to_point = world_point - f.eye;
  const vec3 dir = to_point / dm::sqrt(glm::dot(to_point, to_point));
  const vec3 o = vec3(f.inv_model * glm::vec4(f.eye, 1.0f));
  const vec3 dl = vec3(f.inv_model * glm::vec4(dir, 0.0f)) * f.scale;  // unit in object space
  const glm::vec2 span = box_span(o, dl);
  float t = dm::max(span.x, 0.0f);
  bool hit = false;
  for (int i = 0; i < f.morph.max_steps && t < span.y; ++i) {
    const float d = sdf_morph::mapObject(o + dl * t, f.morph);
    if (d < hit_eps(f, t)) {
      hit = true;
      break;
    }
    t = t + d;
  }
  if (!hit) return false;
  const vec3 p = o + dl * t;
  const vec3 n = object_normal(p, f.morph);
  const vec3 world_hit = f.eye + dir * (t * f.scale);
  const vec3 world_n = f.to_world * n;
  const float view_depth = glm::dot(world_hit - f.eye, f.forward);
  depth = f.depth_scale * (1.0f - f.near_plane / view_depth);
  if (f.morph.surface != SURFACE_COLOUR) {  // the hit's distance from the eye or its normal
    colour = glm::vec4(surfaceOutput(f.morph.surface, t * f.scale, world_n), 1.0f);
    return true;
  }
  if (f.morph.hit_mask) {
    colour = glm::vec4(vec3(sdf_morph::HIT_ID_OBJECT), 1.0f);
    return true;
  }
  const vec3 reflection = exhibit_reflection(f, p, n, sdf_morph::reflectDir(dl, n), t);
  const float ndl = glm::dot(world_n, TO_SUN);
  const float shadow =
      ndl > 0.0f ? sun_visibility(world_hit, world_n, ndl, f.light, {&sun_map, &sun_view()}) : 0.0f;
  const vec3 c = sdf_morph::shadeObjectLit(n, dl, reflection, shadow, 1.0f, f.morph);
  colour = glm::vec4(c, 1.0f);
  return true;
}

// Exhibit 1 as the sun sees it: what the shadow map's pass needs, fixed for the frame.
struct ShadowFrame {
  glm::mat4 inv_model;
  float scale;
  sdf_morph::MorphUniforms morph;
  SunView sun;
  float texel;  // the map's texel in object units: the march's footprint (orthographic, constant)
};

// The sun's ray through a point of the bound's back face (as the sun sees it), marched from where
// it enters the bound; the hit's window depth in the map, or false when it misses.
bool exhibit_sun_depth(const ShadowFrame& f, const vec3& world_point, float& depth) {
  const vec3 o = vec3(f.inv_model * glm::vec4(world_point, 1.0f));
  const vec3 dl = vec3(f.inv_model * glm::vec4(f.sun.forward, 0.0f)) * f.scale;
  const glm::vec2 span = box_span(o, dl);
  const float eps = f.morph.naive ? f.morph.hit_eps : dm::max(MIN_EPS, f.morph.hit_eps * f.texel);
  float t = span.x;
  for (int i = 0; i < f.morph.max_steps && t < span.y; ++i) {
    const float d = sdf_morph::mapObject(o + dl * t, f.morph);
    if (d < eps) {
      const vec3 world_hit = world_point + f.sun.forward * (t * f.scale);
      depth = sun_map_depth(f.sun, glm::dot(world_hit - f.sun.origin, f.sun.forward));
      return true;
    }
    t = t + d;
  }
  return false;
}

std::vector<ShaderUniform> exhibit_uniforms(const ExhibitFrame& f) {
  std::vector<ShaderUniform> u = sdf_morph::morph_shader_uniforms(f.morph);
  ShaderUniform inv{"u_exhibit_inv_model", 16, {}};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) inv.values.push_back(f.inv_model[c][r]);
  u.push_back(inv);
  u.push_back({"u_exhibit_scale", 1, {f.scale}});
  const glm::mat3& m = f.to_world;
  u.push_back({"u_exhibit_to_world0", 3, {m[0].x, m[0].y, m[0].z}});
  u.push_back({"u_exhibit_to_world1", 3, {m[1].x, m[1].y, m[1].z}});
  u.push_back({"u_exhibit_to_world2", 3, {m[2].x, m[2].y, m[2].z}});
  const std::vector<ShaderUniform> l = light_uniforms(f.light);
  u.insert(u.end(), l.begin(), l.end());
  return u;
}

}  // namespace

MeshPass sdf_exhibit_pass(const glm::mat4& model, const sdf_morph::MorphUniforms& morph,
                          const HallLight& light, const ReflectionProbe& probe,
                          const FrameContext& ctx, const CameraModel& cam,
                          const std::string& colour, const std::string& depth) {
  // Exhibit space -> sdf_morph's object space: its pedestal top is the plinth top.
  const glm::mat4 object_to_world =
      glm::translate(model, vec3(0.0f, -sdf_morph::PEDESTAL_HEIGHT, 0.0f));
  ExhibitFrame f;
  f.inv_model = glm::inverse(object_to_world);
  f.scale = glm::length(vec3(model[0]));
  f.to_world = glm::mat3(model) * (1.0f / f.scale);
  f.morph = morph;
  const vec3 sun = vec3(f.inv_model * glm::vec4(TO_SUN, 0.0f)) * f.scale;
  f.morph.boxes[0].dir = sun / dm::sqrt(glm::dot(sun, sun));  // the key light is the sun
  f.morph.key_intensity = SUN_RADIANCE.g;
  f.light = light;
  f.probe = std::make_shared<const ReflectionProbe>(probe);
  f.eye = ctx.camera.origin;
  f.forward = ctx.camera.forward;
  f.pixel_angle = footprint_angle(ctx.camera.tan_half_fov, ctx.height);
  f.near_plane = cam.near_plane;
  f.depth_scale = cam.depth_scale;
  MeshPass p;
  p.name = "exhibit 1: sdf_morph";
  p.mesh = unit_cube();
  const glm::mat4 bound = glm::scale(
      glm::translate(object_to_world, sdf_morph::objectBoundCenter()), BOUND_HALF * 2.0f);
  p.instances = {MeshInstance{bound, glm::vec4(0.0f)}};
  p.colour = colour;
  p.depth = depth;
  p.cull = CullMode::Front;  // back faces only: drawn with the camera inside the bound too
  p.fragment = "museum/sdf_exhibit.frag";
  p.uniforms = exhibit_uniforms(f);
  p.inputs = {{SUN_MAP_TARGET, SUN_MAP_SAMPLER}};
  p.shade_depth = [f](const MeshFragment& frag, glm::vec4& c, float& z) {
    return shade_exhibit(f, frag.world_position, (*frag.inputs)[0], c, z);
  };
  return p;
}

MeshPass sdf_exhibit_shadow_pass(const glm::mat4& model, const sdf_morph::MorphUniforms& morph) {
  const glm::mat4 object_to_world =
      glm::translate(model, vec3(0.0f, -sdf_morph::PEDESTAL_HEIGHT, 0.0f));
  ShadowFrame f;
  f.inv_model = glm::inverse(object_to_world);
  f.scale = glm::length(vec3(model[0]));
  f.morph = morph;
  f.sun = sun_view();
  f.texel = f.sun.texel / f.scale;
  MeshPass p;
  p.name = "sun shadow map: exhibit 1";
  p.mesh = unit_cube();
  const glm::mat4 bound = glm::scale(
      glm::translate(object_to_world, sdf_morph::objectBoundCenter()), BOUND_HALF * 2.0f);
  p.instances = {MeshInstance{bound, glm::vec4(0.0f)}};
  p.colour = "";
  p.depth = SUN_MAP_TARGET;
  p.cull = CullMode::Front;  // back faces, as for the camera
  p.fragment = "museum/sdf_exhibit_shadow.frag";
  p.view = sun_pass_view(f.sun);
  p.uniforms = sdf_morph::morph_shader_uniforms(f.morph);
  ShaderUniform inv{"u_exhibit_inv_model", 16, {}};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) inv.values.push_back(f.inv_model[c][r]);
  p.uniforms.push_back(inv);
  p.uniforms.push_back({"u_exhibit_scale", 1, {f.scale}});
  p.uniforms.push_back({"u_exhibit_texel", 1, {f.texel}});
  const std::vector<ShaderUniform> sun = sun_view_uniforms(f.sun);
  p.uniforms.insert(p.uniforms.end(), sun.begin(), sun.end());
  p.shade_depth = [f](const MeshFragment& frag, glm::vec4& c, float& z) {
    c = glm::vec4(1.0f);
    return exhibit_sun_depth(f, frag.world_position, z);
  };
  return p;
}

}  // namespace sdfreel::museum
