#pragma once
// light_beams: how much of a light a point sees. The light is an extended shape; every other
// shape (the other lights, the beams, the occluder) can hide part of it. Three estimators, from
// the seed's to the exact one (uniforms.h, Estimator), plus a stratified Monte Carlo that checks
// the exact one (tests/scenes/light_beams).
#include "scenes/light_beams/uniforms.h"
#include "scenes/scene.h"

namespace sdfreel::light_beams {

// The seed's getNearestDist(pos, shapeIndex): distance to the nearest shape other than `skip`.
float nearestDist(vec2 p, int skip, const BeamsUniforms& u, RayStats& stats);

// The seed's shadow: march from p toward the closest point of the light (at dist_to_light), with
// the seed's minimum hit distance and clamped steps: 1 if the ray gets there, else 0.
float seedShadow(vec2 p, int light, float dist_to_light, const BeamsUniforms& u, RayStats& stats);

// The share of the light's angular span seen from p (outside the light) that no other shape
// hides: the product of each shape's unhidden share (exact for one occluder), or the exact union.
float penumbraVisibility(vec2 p, int light, const BeamsUniforms& u, RayStats& stats);
float exactVisibility(vec2 p, int light, const BeamsUniforms& u, RayStats& stats);

// The estimator of u, for a point at distance dist_to_light > 0 from the light.
float lightVisibility(vec2 p, int light, float dist_to_light, const BeamsUniforms& u,
                      RayStats& stats);

// The same share by `rays` rays at the centres of equal angle strata of the light's span, each
// visible when its first hit among all shapes is the light. Errs at most 1/(2 rays) per edge of
// a shadow in the span. For tests: scalar, double-free, slow.
float monteCarloVisibility(vec2 p, int light, const BeamsUniforms& u, int rays);

}  // namespace sdfreel::light_beams
