#pragma once
// water_lily's soft shadows (Quilez's improved form): the constants and the span a shadow ray
// marches, shared by the scalar softShadow (render.cpp) and its eight-lane twin (lanes.cpp).
#include <glm/glm.hpp>

#include "scenes/water_lily/uniforms.h"

namespace sdfreel::water_lily {

constexpr float SHADOW_TMIN = 0.01f;
constexpr float SHADOW_HIT_EPS = 1e-4f;
constexpr float SHADOW_FIRST_PH = 1e10f;
constexpr float SHADOW_MIN_DENOM = 1e-6f;
constexpr float SHADOW_MIN_STEP = 1e-4f;  // a bound near 0 beside a petal must not stall the ray
constexpr float FILL_SHADOW_SOFTNESS = 0.35f;  // the sky fill is a wide light: a softer penumbra

// (first t, tmax) of the shadow ray from ro towards ld: the field box's span (naive: 0 to
// max_dist), starting at SHADOW_TMIN at least.
glm::vec2 shadowSpan(const glm::vec3& ro, const glm::vec3& ld, const LilyUniforms& u);

}  // namespace sdfreel::water_lily
