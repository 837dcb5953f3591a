#pragma once
// Crepuscular rays as an image pass: seed 004's loop (GPU Gems 3, chapter 13, Mitchell,
// "Volumetric Light Scattering as a Post-Process", as the seed writes it) over an occlusion target
// (x = 1 where the light is seen, 0 where something hides it). For each pixel at uv: delta =
// (uv - light_uv) * density / N; N taps from the pixel's own towards the light, tap k weighted
// weight * decay^k: c = occ(uv) * weight; decay_acc = decay; N - 1 times: uv -= delta, c +=
// occ(uv) * decay_acc * weight, decay_acc *= decay; the result is c * exposure * fade. With
// density = exposure = 1 this is the seed's loop (it has neither); a decay below 1 makes a shaft
// fade along its length, brightest by the light.
// - Banding: the march (not the pixel's own tap) starts delta * j further along, j in [0, 1) from
//   an integer hash of the pixel (never fract(sin(x) * 43758.5453), which CPUs and GPUs differ on).
// - Borders: the march stops when uv leaves [0, 1]^2 (no streaks from clamped edge texels).
// - Light off screen or behind the camera: `fade` goes from 1 (light within FADE_START_COS of the
//   view axis) to 0 (light at 90 degrees or behind), so the rays fade out instead of popping.
// The GLSL twin is shaders/common/crepuscular_rays.glsl; both give the same bits.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "render/camera_model.h"
#include "render/frame_plan.h"

namespace sdfreel {

struct CrepuscularRays {
  glm::vec2 light_uv{0.5f};  // the light's image position, [0, 1]^2 on screen, y down
  float fade = 1.0f;         // crepuscular_light(): 1 facing the light, 0 behind the camera
  int samples = 128;         // seed 004's NUM_SAMPLES
  // The seed's loop has only weight and decay. GPU Gems 3's constants as the start (Sanglard's
  // port, techniques.md): its weight 5.65 times its exposure 0.0034 is the weight here, and the
  // decay, 1 there (no fading), is below 1 as the seed's loop means it.
  float density = 1.0f, weight = 5.65f * 0.0034f, decay = 0.98f, exposure = 1.0f;
  uint32_t jitter_seed = 4;  // below 2^24: GL uniforms travel as floats
};

// The light's image position and fade for a light in direction `to_light` (world, unit) seen by
// `cam`: light_uv from the camera model's view and projection.
constexpr float FADE_START_COS = 0.5f;  // full strength within 60 degrees of the view axis
void crepuscular_light(CrepuscularRays& rays, const CameraModel& cam, const glm::vec3& to_light);

// The pass's value at pixel (x, y) of the occlusion image (rgb = the scattered light, alpha 1).
glm::vec4 crepuscular_rays_pixel(const CrepuscularRays& rays, const ImageRGBA& occlusion, int x,
                                 int y);

// An image pass reading `occlusion` (sampler u_occlusion), writing `output`.
ImagePass crepuscular_rays_pass(const CrepuscularRays& rays, const std::string& occlusion,
                                const std::string& output);

}  // namespace sdfreel
