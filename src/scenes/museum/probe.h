#pragma once
// The reflection probe of exhibit 1 (seed 004's image-based reflections): a cube map of the hall
// seen from the exhibit's centre, rendered when the centre moves by casting each texel's ray
// against the hall's boxes (exact for this hall of boxes: no rasterisation of six views needed)
// and shading the hit as the hall pass does (or the sky through the window). Both backends read the
// same texels: the CPU through sample_probe, GL through the texture u_probe with the same bilinear
// filter in code (shaders/museum/probe.glsl).
#include <glm/glm.hpp>
#include <vector>

#include "render/shader_inputs.h"
#include "scenes/museum/lighting.h"

namespace sdfreel::museum {

constexpr int PROBE_SIZE = 128;  // texels per cube face edge

// Faces +x, -x, +y, -y, +z, -z stacked vertically: PROBE_SIZE x 6 * PROBE_SIZE, RGBA.
struct ReflectionProbe {
  glm::vec3 centre{0.0f};
  std::vector<float> texels;
};

ReflectionProbe render_probe(const glm::vec3& centre, const std::vector<HallBox>& boxes,
                             const HallLight& light);

// Bilinear within the face that direction d (unit or not) points into.
glm::vec3 sample_probe(const ReflectionProbe& probe, const glm::vec3& d);

ShaderTexture probe_texture(const ReflectionProbe& probe);

}  // namespace sdfreel::museum
