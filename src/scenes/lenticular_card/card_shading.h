#pragma once
// What card.cpp's one ray and card_lanes.cpp's eight share: the card's shading constants and its
// texel reads (the GLSL twin, shaders/lenticular_card/card.glsl, holds the same numbers).
#include <glm/glm.hpp>

#include "scenes/common/texture.h"
#include "scenes/lenticular_card/card.h"

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

// texelFetchRepeat(*tex.print, column, row), through tex.print_by_strip when there is one.
inline glm::vec4 print_texel(const CardTextures& tex, int views, float column, float row) {
  if (!tex.print_by_strip) return texelFetchRepeat(*tex.print, column, row);
  const int x = wrap_texel(column, tex.print->width), y = wrap_texel(row, tex.print->height);
  const float* c = tex.print_by_strip->at(x / views, (x % views) * tex.print->height + y);
  return glm::vec4(c[0], c[1], c[2], c[3]);
}

}  // namespace sdfreel::lenticular_card
