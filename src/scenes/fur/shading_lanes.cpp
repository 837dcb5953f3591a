// The shell and case fragments of the fur, eight at a time (MeshPass::shade8): shade_shell and
// shade_case line for line in lanes, branches as selects. The hit-id and surface modes (passes
// and the bench's masks, not the picture) shade each lane with the one-fragment function.
#include "scenes/fur/shading_lanes.h"

#include "scenes/common/surface_output.h"
#include "scenes/fur/strand_hash.h"

namespace sdfreel::fur {
namespace {

// glm::normalize: v * (1 / sqrt(dot(v, v))).
V3x8 normalize(const V3x8& v) {
  return v * (1.0f / dm::sqrt(vdot(v, v)));
}

template <class Shade>
void one_by_one(const MeshFragments8& f, FragmentColours8& out, Shade shade) {
  MeshFragment one;
  one.instance_data = f.instance_data;
  one.front_facing = f.front_facing;
  one.inputs = f.inputs;
  for (int k = 0; k < LANES; ++k) {
    one.world_position = f.world_position.lane(k);
    one.world_normal = f.world_normal.lane(k);
    one.uv = glm::vec2(f.uv.x[k], f.uv.y[k]);
    const glm::vec4 c = shade(one);
    out.r[k] = c.r, out.g[k] = c.g, out.b[k] = c.b, out.a[k] = c.a;
  }
}

}  // namespace

void shade_shell8(const ShellLook& look, const MeshFragments8& f, FragmentColours8& out) {
  if (look.hit_id >= 0.0f || look.surface != SURFACE_COLOUR)
    return one_by_one(f, out, [&](const MeshFragment& one) { return shade_shell(look, one); });
  const float h = f.instance_data.x, ao = f.instance_data.y;
  const V2x8 uvd = f.uv * look.density;
  const V2x8 cell{dm::floor(uvd.x), dm::floor(uvd.y)};
  const V2x8 local = (uvd - cell) * 2.0f - 1.0f;
  const F8 rnd = dm::mix(splat(STRAND_MIN), splat(STRAND_MAX),
                         strand_random(dm::to_int(cell.x), dm::to_int(cell.y)));
  const M8 gap = splat_mask(h > 0.0f) & (vlength(local) > look.thickness * (rnd - h));
  const V3x8 n = normalize(f.world_normal);
  F8 lit = dm::clamp(vdot(n, look.light_dir), 0.0f, 1.0f) * 0.5f + 0.5f;
  lit = lit * lit;
  const glm::vec3 albedo = dm::mix(look.base, look.tip, h);
  const F8 zero = splat(0.0f);
  out.r = select(gap, zero, albedo.r * (look.light.r * lit + look.ambient.r) * ao);
  out.g = select(gap, zero, albedo.g * (look.light.g * lit + look.ambient.g) * ao);
  out.b = select(gap, zero, albedo.b * (look.light.b * lit + look.ambient.b) * ao);
  out.a = select(gap, zero, splat(1.0f));
}

void shade_case8(const CaseLook& look, const MeshFragments8& f, FragmentColours8& out) {
  if (look.hit_mask || look.surface != SURFACE_COLOUR)
    return one_by_one(f, out, [&](const MeshFragment& one) { return shade_case(look, one); });
  const V3x8 n = normalize(f.world_normal);
  const F8 lambert = dm::max(vdot(n, look.light_dir), 0.0f);
  F8 shadow = splat(1.0f);
  for (const glm::vec4& b : look.bodies) {
    const V2x8 d{f.world_position.x - b.x, f.world_position.z - b.z};
    const F8 across = vlength(d) / (b.w * 1.3f);
    const F8 above = (b.y - f.world_position.y) / b.w;
    const F8 a = dm::clamp(1.0f - across, 0.0f, 1.0f) * dm::clamp(1.6f - 0.3f * above, 0.0f, 1.0f);
    shadow = shadow * (1.0f - 0.6f * a * a * dm::clamp(n.y, 0.0f, 1.0f));
  }
  const glm::vec3 albedo(f.instance_data);
  out.r = albedo.r * (look.light.r * lambert + look.ambient.r) * shadow;
  out.g = albedo.g * (look.light.g * lambert + look.ambient.g) * shadow;
  out.b = albedo.b * (look.light.b * lambert + look.ambient.b) * shadow;
  out.a = splat(1.0f);
}

}  // namespace sdfreel::fur
