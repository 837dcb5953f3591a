#pragma once
// What card.cpp's one ray and card_lanes.cpp's eight share: the card's shading constants, its
// texel reads and its shading, written once over one ray (glm::vec3, float) or eight (V3x8, F8)
// with the same operations in the same order, so both give the same bits (the GLSL twin,
// shaders/lenticular_card/card.glsl, holds the same numbers and steps).
#include <glm/glm.hpp>

#include "scenes/common/texture.h"
#include "scenes/lenticular_card/card.h"
#include "scenes/lenticular_card/card_texels_lanes.h"
#include "scenes/lenticular_card/textures.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"
#include "sdf/lanes_exp_log.h"

namespace sdfreel::lenticular_card {

constexpr float BIG = 3.0e38f;
constexpr float HIT_ID_CARD = 1.0f, HIT_ID_STAND = 2.0f;
constexpr float AMBIENT = 0.25f, KEY = 1.1f;
constexpr float RIDGE_SLOPE = 0.35f;  // the lens profile's normal tilt at a lens edge
// The noise map is stretched along the lenses (the seed stretches it along y): few cycles along
// the card's height, one across each lens.
constexpr float RIDGE_NOISE_ACROSS = 0.0625f, RIDGE_NOISE_ALONG = 1.5f;
constexpr float F0 = 0.048f;  // ((n - 1) / (n + 1))^2 for n = 1.56
constexpr float SHININESS = 60.0f, SPECULAR = 0.6f;
inline const glm::vec3 PAPER(0.72f, 0.70f, 0.66f), EDGE(0.09f, 0.09f, 0.1f),
    WOOD(0.12f, 0.075f, 0.045f);
inline const glm::vec3 ENV_LOW(0.05f, 0.045f, 0.04f), ENV_HIGH(0.65f, 0.68f, 0.75f);

// The sheet's normal before normalising: the lens profile across each lens plus the stretched
// noise map.
inline glm::vec3 ridge_tilt(float lens_coord, float across, float y, const CardUniforms& u,
                            const CardTextures& tex) {
  const glm::vec4 n = sampleBilinear(
      *tex.ridges, glm::vec2(lens_coord * RIDGE_NOISE_ACROSS, y * RIDGE_NOISE_ALONG));
  return glm::vec3(across * RIDGE_SLOPE + n.x * u.ridge_noise, n.y * u.ridge_noise, 1.0f);
}

// texelFetchRepeat(print, column, row), through the strips when there are.
inline glm::vec4 print_texel(const CardTextures& tex, float column, float row) {
  if (!tex.print) return texelFetchRepeat(*tex.plain_print, column, row);
  return tex.print->texel(wrap_texel(column, tex.print->width), wrap_texel(row, tex.print->height));
}

// The print's albedo and the sheet's tilted normal (before normalising) at a point of the face:
// texel reads, one ray's or eight lanes'.
inline void face_texels(const CardTextures& tex, const CardUniforms& u, float column, float row,
                        float lens_coord, float across, float y, glm::vec3& albedo,
                        glm::vec3& tilt) {
  albedo = glm::vec3(print_texel(tex, column, row));
  tilt = ridge_tilt(lens_coord, across, y, u, tex);
}
inline void face_texels(const CardTextures& tex, const CardUniforms& u, F8 column, F8 row,
                        F8 lens_coord, F8 across, F8 y, V3x8& albedo, V3x8& tilt) {
  if (tex.print) {  // the strips: gathers (card_texels_lanes.h)
    albedo = print_texels(*tex.print, column, row);
    const V2x8 n = bilinear_xy(*tex.ridges, lens_coord * RIDGE_NOISE_ACROSS, y * RIDGE_NOISE_ALONG);
    tilt = V3x8(across * RIDGE_SLOPE + n.x * u.ridge_noise, n.y * u.ridge_noise, splat(1.0f));
    return;
  }
  for (int i = 0; i < LANES; ++i) {
    glm::vec3 a, n;
    face_texels(tex, u, column[i], row[i], lens_coord[i], across[i], y[i], a, n);
    albedo.set_lane(i, a);
    tilt.set_lane(i, n);
  }
}

template <class V>
V normalize3(const V& v) {
  return v * (1.0f / dm::sqrt(vdot(v, v)));
}

template <class V>
V matte(const glm::vec3& albedo, const V& n, const glm::vec3& light) {
  return V(albedo) * (AMBIENT + KEY * dm::max(vdot(n, light), 0.0f));
}

// A constant as one ray's value or eight lanes'.
inline float broadcast(float v, float) {
  return v;
}
inline F8 broadcast(float v, F8) {
  return splat(v);
}

// What the glossy sheet reflects: a dark floor below, a bright room above.
template <class V>
V environment(const V& r) {
  const auto s = dm::smoothstep(-0.1f, 0.5f, r.y);
  return V(dm::mix(broadcast(ENV_LOW.x, s), broadcast(ENV_HIGH.x, s), s),
           dm::mix(broadcast(ENV_LOW.y, s), broadcast(ENV_HIGH.y, s), s),
           dm::mix(broadcast(ENV_LOW.z, s), broadcast(ENV_HIGH.z, s), s));
}

// The radiance of the card's front at local point p seen along local direction d.
template <class V, class S>
V front_colour(const V& p, const V& d, const CardUniforms& u, const CardTextures& tex) {
  const float lenses = float(u.lenses), views = float(u.views), rows = float(u.view_height);
  const S lens_coord = (p.x + CARD_HALF_WIDTH) * (lenses / (2.0f * CARD_HALF_WIDTH));
  const S lens = dm::clamp(dm::floor(lens_coord), 0.0f, lenses - 1.0f);
  const S across = lens_coord - lens - 0.5f;
  // The viewing angle across the lenses: the view direction projected on the xz plane.
  const S vx = -d.x, vz = -d.z;
  const S len = dm::sqrt(vx * vx + vz * vz);
  const S zero{};
  const S sin_theta = select(len > 0.0f, vx / len, zero);
  // seen_print_position(lens + 0.5, sin_theta, ior, thickness), written out (optics.h).
  const S s = sin_theta / u.ior;
  const S x = (lens + 0.5f) - u.thickness * (s / dm::sqrt(1.0f - s * s));
  const S column = dm::clamp(dm::floor(x * views), 0.0f, lenses * views - 1.0f);
  const S down = (CARD_CENTRE_Y + CARD_HALF_HEIGHT - p.y) * (0.5f / CARD_HALF_HEIGHT);
  const S row = dm::floor((down + u.scroll) * rows);
  V albedo, tilt;
  face_texels(tex, u, column, row, lens_coord, across, p.y, albedo, tilt);
  const V n = normalize3(tilt);
  const V v = normalize3(-d);
  const V diffuse = albedo * (AMBIENT + KEY * dm::max(u.light.z, 0.0f));
  const S n_dot_v = vdot(n, v);
  const S cos_v = dm::max(n_dot_v, 0.0f);
  const S m = 1.0f - cos_v, m2 = m * m;
  const S fresnel = F0 + (1.0f - F0) * (m2 * m2 * m);
  const V r = n * (2.0f * n_dot_v) - v;
  const V h = normalize3(u.light + v);
  const S spec = SPECULAR * KEY * dm::pow(dm::max(vdot(n, h), 0.0f), SHININESS);
  return diffuse * (1.0f - fresnel) + (environment(r) * fresnel + V(spec, spec, spec)) * u.gloss;
}

}  // namespace sdfreel::lenticular_card
