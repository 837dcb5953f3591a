#include "scenes/lantern_festival/shading.h"

namespace sdfreel::lantern_festival {

namespace {

// The seed's paper texture weights.
constexpr float NORMAL_NOISE_WEIGHT = 0.35f;
constexpr float ALBEDO_NOISE_WEIGHT = 0.4f;
const glm::vec2 PAPER_UV_REPEAT(2.0f, 1.0f);
// Phong exponents and specular strengths per material.
constexpr float PAPER_SHININESS = 8.0f, PAPER_SPECULAR = 0.08f;
constexpr float METAL_SHININESS = 40.0f, METAL_SPECULAR = 1.2f;
constexpr float WOOD_SHININESS = 6.0f, WOOD_SPECULAR = 0.04f;
// mix(0.3, 0.8, flickerValue) of the seed, and its value at the middle of the flicker range.
constexpr float FLICKER_LO = 0.3f, FLICKER_HI = 0.8f, FLICKER_MID = 0.55f;

struct Light {
  glm::vec3 dir;       // towards the light, unit
  glm::vec3 radiance;  // arriving (after 1/d^2)
};

glm::vec3 reflect3(const glm::vec3& i, const glm::vec3& n) {
  return i - n * (2.0f * glm::dot(n, i));
}

float phong(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, float shininess) {
  const float rv = glm::dot(reflect3(-l, n), v);
  return rv > 0.0f ? dm::pow(rv, shininess) : 0.0f;
}

Light candleLight(const LightFrame& L, const GridFrame& g, const LanternHit& h) {
  const glm::vec3 light_pos = h.cell.center + toWorld(h.cell, L.candle_local * g.scale);
  const glm::vec3 to_light = light_pos - h.p;
  const float d2 = dm::max(glm::dot(to_light, to_light), 1e-6f);
  // Lantern units for the falloff, so that a scaled lantern glows the same.
  const float d2_local = d2 * g.inv_scale * g.inv_scale;
  return Light{to_light / dm::sqrt(d2), L.candle_color * (candleStrength(L, h.cell) / d2_local)};
}

// Opaque Lambert + Phong from the moon and the candle, plus the sky's fill light.
glm::vec3 shadeOpaque(const LightFrame& L, const GridFrame& g, const LanternHit& h,
                      const glm::vec3& albedo, float shininess, float specular) {
  const Light candle = candleLight(L, g, h);
  const float moon_ndl = dm::max(glm::dot(h.n, L.moon_dir), 0.0f);
  const float candle_ndl = dm::max(glm::dot(h.n, candle.dir), 0.0f);
  glm::vec3 col = albedo * (L.moon_light * moon_ndl + candle.radiance * candle_ndl + L.ambient);
  col += L.moon_light * (specular * phong(h.n, L.moon_dir, h.view, shininess));
  col += candle.radiance * (specular * phong(h.n, candle.dir, h.view, shininess));
  return col;
}

}  // namespace

// flicker_strength 0 blends to the steady middle value, nothing divides by it
// (tests/hard_cases/lantern_festival/flicker_zero).
float candleStrength(const LightFrame& L, const LanternCell& cell) {
  const float flicker =
      dm::mix(FLICKER_LO, FLICKER_HI, flickerValue(L.flicker_time + cell.flicker_phase));
  return dm::max(0.0f, dm::mix(FLICKER_MID, flicker, L.flicker_strength));
}

glm::vec3 shadePaper(const LightFrame& L, const GridFrame& g, const LanternHit& h) {
  glm::vec3 albedo = L.paper_albedo;
  const glm::vec2 normalXZ = radialDirection(h.local);
  const glm::vec2 uv = calcCylindricalUVs(normalXZ, h.local);
  glm::vec3 normalNoise = glm::vec3(sampleBilinear(*L.paper_normal, uv * PAPER_UV_REPEAT));
  normalNoise = normalNoise * 2.0f - 1.0f;
  const float noise = sampleBilinear(*L.paper_noise, uv * PAPER_UV_REPEAT).x;
  // The map is tangent-space: x along increasing longitude, y up the lantern, z along the normal.
  const glm::vec3 tangent = toWorld(h.cell, glm::vec3(normalXZ.y, 0.0f, -normalXZ.x));
  const glm::vec3 up = h.cell.to_local[1];
  const glm::vec3 n =
      safe_normalize(h.n + (tangent * normalNoise.x + up * normalNoise.y + h.n * normalNoise.z) *
                               NORMAL_NOISE_WEIGHT);
  albedo *= 1.0f - noise * ALBEDO_NOISE_WEIGHT;

  // Candle: the seed's abs(n.l) * strength / d^2 lights both faces (translucent paper).
  const Light candle = candleLight(L, g, h);
  const glm::vec3 light = candle.radiance * dm::abs(glm::dot(n, candle.dir));
  const float moon_ndl = dm::max(glm::dot(n, L.moon_dir), 0.0f);
  glm::vec3 col = albedo * (light + L.moon_light * moon_ndl + L.ambient);
  col += L.moon_light * (PAPER_SPECULAR * phong(n, L.moon_dir, h.view, PAPER_SHININESS));
  col += candle.radiance * (PAPER_SPECULAR * phong(n, candle.dir, h.view, PAPER_SHININESS));
  return col;
}

glm::vec3 shadeMetal(const LightFrame& L, const GridFrame& g, const LanternHit& h) {
  return shadeOpaque(L, g, h, L.metal_albedo, METAL_SHININESS, METAL_SPECULAR);
}

glm::vec3 shadeWood(const LightFrame& L, const GridFrame& g, const LanternHit& h) {
  return shadeOpaque(L, g, h, L.wood_albedo, WOOD_SHININESS, WOOD_SPECULAR);
}

glm::vec3 shadeLantern(const LightFrame& L, const GridFrame& g, const LanternHit& h) {
  switch (nearestPart(h.local)) {
    case LanternPart::Metal:
      return shadeMetal(L, g, h);
    case LanternPart::Paper:
      return shadePaper(L, g, h);
    default:
      return shadeWood(L, g, h);
  }
}

}  // namespace sdfreel::lantern_festival
