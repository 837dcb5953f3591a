#include "render/passes/crepuscular_rays.h"

#include "render/passes/crepuscular_rays_rows.h"
#include "sdf/det_math.h"
#include "sdf/noise.h"

namespace sdfreel {

void crepuscular_light(CrepuscularRays& rays, const CameraModel& cam, const glm::vec3& to_light) {
  // View space: the camera looks down -z, so the cosine to the view axis is -z.
  const glm::vec4 v = cam.view * glm::vec4(to_light, 0.0f);
  const float cos_axis = -v.z;
  rays.fade = dm::smoothstep(0.0f, FADE_START_COS, cos_axis);
  if (cos_axis <= 0.0f) {  // behind: no meaningful projection; fade is 0 anyway
    rays.light_uv = glm::vec2(0.5f);
    return;
  }
  const glm::vec4 clip = cam.projection * v;  // a direction: the light at infinity
  rays.light_uv = glm::vec2(0.5f + 0.5f * clip.x / clip.w, 0.5f - 0.5f * clip.y / clip.w);
}

namespace {

float occlusion_at(const ImageRGBA& occ, glm::vec2 uv) {
  const int x = int(dm::floor(uv.x * float(occ.width)));
  const int y = int(dm::floor(uv.y * float(occ.height)));
  return occ.at(x < occ.width ? x : occ.width - 1, y < occ.height ? y : occ.height - 1)[0];
}

bool outside(glm::vec2 uv) {
  return uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f;
}

}  // namespace

glm::vec4 crepuscular_rays_pixel(const CrepuscularRays& r, const ImageRGBA& occ, int x, int y) {
  if (!(r.fade > 0.0f)) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  glm::vec2 uv((float(x) + 0.5f) / float(occ.width), (float(y) + 0.5f) / float(occ.height));
  const glm::vec2 delta = (uv - r.light_uv) * (r.density / float(r.samples));
  float c = occlusion_at(occ, uv) * r.weight;  // the seed's first tap: the pixel's own
  const float jitter = hash_to_unit(hash2i(x, y, r.jitter_seed));
  uv = uv - delta * jitter;
  float decay_acc = r.decay;
  for (int i = 1; i < r.samples; ++i) {
    uv = uv - delta;
    if (outside(uv)) break;
    c = c + occlusion_at(occ, uv) * decay_acc * r.weight;
    decay_acc = decay_acc * r.decay;
  }
  const float v = c * r.exposure * r.fade;
  return glm::vec4(v, v, v, 1.0f);
}

ImagePass crepuscular_rays_pass(const CrepuscularRays& r, const std::string& occlusion,
                                const std::string& output) {
  ImagePass p;
  p.name = "crepuscular rays";
  p.inputs = {{occlusion, "u_occlusion"}};
  p.output = output;
  p.shader = "common/crepuscular_rays.glsl";
  p.uniforms = {{"u_rays.light_uv", 2, {r.light_uv.x, r.light_uv.y}},
                {"u_rays.fade", 1, {r.fade}},
                {"u_rays.samples", 1, {float(r.samples)}},
                {"u_rays.density", 1, {r.density}},
                {"u_rays.weight", 1, {r.weight}},
                {"u_rays.decay", 1, {r.decay}},
                {"u_rays.exposure", 1, {r.exposure}},
                {"u_rays.jitter_seed", 1, {float(r.jitter_seed)}}};
  p.pixel = [r](const ImageInputs& in, int x, int y) {
    return crepuscular_rays_pixel(r, in[0], x, y);
  };
  p.rows = [r](const ImageInputs& in) { return crepuscular_rays_rows(r, in[0]); };
  return p;
}

}  // namespace sdfreel
