#include "scenes/fur/shell_shading.h"

#include "scenes/common/surface_output.h"
#include "scenes/fur/strand_hash.h"
#include "sdf/det_math.h"

namespace sdfreel::fur {

// Fake ambient occlusion: clamp(h^AO_POWER + AO_BIAS, 0, 1) (Acerola's attenuation 2.04).
constexpr float AO_POWER = 2.04f, AO_BIAS = 0.18f;

glm::vec4 shell_data(int i, int n, float curvature) {
  const float h = float(i) / float(n);
  const float ao = dm::clamp(dm::pow(h, AO_POWER) + AO_BIAS, 0.0f, 1.0f);
  return glm::vec4(h, ao, dm::pow(h, 1.0f + curvature), float(i));
}

PlacedVertex place_shell_vertex(const ShellMotion& m, const MeshInstance& inst,
                                const glm::vec3& position, const glm::vec3& normal) {
  const glm::vec3 world_normal = glm::mat3(inst.model) * normal;
  glm::vec3 world = glm::vec3(inst.model * glm::vec4(position, 1.0f));
  world += glm::normalize(world_normal) * (m.length * inst.data.x);
  const float k = inst.data.z;
  const glm::vec3 rel = world - m.centre;
  world = m.centre + dm::mix(rel, m.twist * rel, k) + m.offset * k;
  return {world, world_normal};
}

glm::vec4 shade_shell(const ShellLook& look, const MeshFragment& f) {
  const float h = f.instance_data.x, ao = f.instance_data.y;
  const glm::vec2 uvd = f.uv * look.density;
  const glm::vec2 cell(dm::floor(uvd.x), dm::floor(uvd.y));
  const glm::vec2 local = (uvd - cell) * 2.0f - 1.0f;
  const float rnd = dm::mix(STRAND_MIN, STRAND_MAX, strand_random(int(cell.x), int(cell.y)));
  if (h > 0.0f && glm::length(local) > look.thickness * (rnd - h)) return glm::vec4(0.0f);
  if (look.hit_id >= 0.0f) return glm::vec4(glm::vec3(look.hit_id), 1.0f);
  const glm::vec3 n = glm::normalize(f.world_normal);
  if (look.surface != SURFACE_COLOUR)
    return glm::vec4(surfaceOutput(look.surface, glm::length(f.world_position - look.eye), n),
                     1.0f);
  // The seed's half-Lambert: N.L clamped, then * 0.5 + 0.5, squared.
  float lit = dm::clamp(glm::dot(n, look.light_dir), 0.0f, 1.0f) * 0.5f + 0.5f;
  lit = lit * lit;
  const glm::vec3 albedo = dm::mix(look.base, look.tip, h);
  return glm::vec4(albedo * (look.light * lit + look.ambient) * ao, 1.0f);
}

}  // namespace sdfreel::fur
