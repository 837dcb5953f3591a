// Crepuscular rays (GPU Gems 3, ch. 13) as an image pass: the GLSL twin of
// src/render/passes/crepuscular_rays.cpp (same operations in the same order; see there for the
// algorithm, the jitter, the border stop and the fade).
#include "common/image_pass.glsl"
#include "common/noise.glsl"

struct CrepuscularRays {
  vec2 light_uv;
  float fade;
  int samples;
  float density;
  float weight;
  float decay;
  float exposure;
  uint jitter_seed;
};
uniform CrepuscularRays u_rays;
uniform sampler2D u_occlusion;

float occlusion_at(vec2 uv) {
  precise float fx = floor(uv.x * float(u_resolution.x));
  precise float fy = floor(uv.y * float(u_resolution.y));
  int x = min(int(fx), u_resolution.x - 1);
  int y = min(int(fy), u_resolution.y - 1);
  return read_image(u_occlusion, ivec2(x, y)).x;
}

bool outside(vec2 uv) {
  return uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0;
}

void main() {
  ivec2 p = image_pixel();
  if (!(u_rays.fade > 0.0)) {
    frag_out = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  precise vec2 uv = vec2((float(p.x) + 0.5) / float(u_resolution.x),
                         (float(p.y) + 0.5) / float(u_resolution.y));
  precise vec2 delta = (uv - u_rays.light_uv) * (u_rays.density / float(u_rays.samples));
  precise float c = occlusion_at(uv) * u_rays.weight;  // the seed's first tap: the pixel's own
  precise float jitter = hash_to_unit(hash2i(p.x, p.y, u_rays.jitter_seed));
  uv = uv - delta * jitter;
  precise float decay_acc = u_rays.decay;
  for (int i = 1; i < u_rays.samples; ++i) {
    uv = uv - delta;
    if (outside(uv)) break;
    c = c + occlusion_at(uv) * decay_acc * u_rays.weight;
    decay_acc = decay_acc * u_rays.decay;
  }
  precise float v = c * u_rays.exposure * u_rays.fade;
  frag_out = vec4(v, v, v, 1.0);
}
