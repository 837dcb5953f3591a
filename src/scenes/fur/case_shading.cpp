#include "scenes/fur/case_shading.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/common/surface_output.h"
#include "sdf/det_math.h"

namespace sdfreel::fur {

std::shared_ptr<const TriangleMesh> box_mesh() {
  static const std::shared_ptr<const TriangleMesh> mesh = [] {
    TriangleMesh m;
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      const float sign = face % 2 ? -1.0f : 1.0f;
      glm::vec3 n(0.0f), du(0.0f), dv(0.0f);
      n[axis] = sign;
      du[(axis + 1) % 3] = 1.0f;
      dv[(axis + 2) % 3] = 1.0f;
      if (sign < 0.0f) std::swap(du, dv);  // du x dv points out
      const unsigned base = unsigned(m.vertex_count());
      for (int c = 0; c < 4; ++c) {
        const float a = (c == 1 || c == 2) ? 1.0f : -1.0f, b = c >= 2 ? 1.0f : -1.0f;
        const glm::vec3 p = n + du * a + dv * b;
        m.positions.insert(m.positions.end(), {p.x, p.y, p.z});
        m.normals.insert(m.normals.end(), {n.x, n.y, n.z});
        m.uvs.insert(m.uvs.end(), {a * 0.5f + 0.5f, b * 0.5f + 0.5f});
      }
      m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return std::make_shared<const TriangleMesh>(std::move(m));
  }();
  return mesh;
}

MeshInstance box_instance(const glm::mat4& model, const glm::vec3& centre, const glm::vec3& half,
                          const glm::vec3& colour) {
  MeshInstance i;
  i.model = glm::scale(glm::translate(model, centre), half);
  i.data = glm::vec4(colour, 0.0f);
  return i;
}

glm::vec4 shade_case(const CaseLook& look, const MeshFragment& f) {
  if (look.hit_mask) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const glm::vec3 n = glm::normalize(f.world_normal);
  if (look.surface != SURFACE_COLOUR)
    return glm::vec4(surfaceOutput(look.surface, glm::length(f.world_position - look.eye), n),
                     1.0f);
  const float lambert = dm::max(glm::dot(n, look.light_dir), 0.0f);
  float shadow = 1.0f;
  for (const glm::vec4& b : look.bodies) {
    const glm::vec2 d(f.world_position.x - b.x, f.world_position.z - b.z);
    const float across = glm::length(d) / (b.w * 1.3f);
    const float above = (b.y - f.world_position.y) / b.w;
    const float a =
        dm::clamp(1.0f - across, 0.0f, 1.0f) * dm::clamp(1.6f - 0.3f * above, 0.0f, 1.0f);
    shadow *= 1.0f - 0.6f * a * a * dm::clamp(n.y, 0.0f, 1.0f);
  }
  const glm::vec3 albedo(f.instance_data);
  return glm::vec4(albedo * (look.light * lambert + look.ambient) * shadow, 1.0f);
}

}  // namespace sdfreel::fur
