#pragma once
// light_beams rendering: the camera ray's point on the plane z = 0 (the 2D world), each light's
// glow there with its visibility, over the seed's background.
#include <glm/glm.hpp>

#include "scenes/light_beams/uniforms.h"
#include "scenes/scene.h"

namespace sdfreel::light_beams {

// The glow formula: 1 / (constant + linear * d + quadratic * d^2).
float attenuation(float d, const BeamsUniforms& u);

// 1 at the frame's centre, 0 at its corners (the default view's frame, in world units): the
// beams fade toward them.
float cornerFade(vec2 p);

// Light i's emission at p: white (times its gain) inside, the coloured glow times its visibility
// outside, blended from white to the glow over aa_width (the seed's pseudo anti-aliasing).
glm::vec3 lightEmission(vec2 p, int i, float aa_width, const BeamsUniforms& u, RayStats& stats);

// Linear radiance at the 2D point p whose pixel is `footprint` world units wide.
glm::vec3 radianceAt(vec2 p, float footprint, const BeamsUniforms& u, RayStats& stats);

// Linear radiance along a primary ray: its point on the plane z = 0, or the background.
glm::vec3 sceneRadiance(const Ray& ray, const BeamsUniforms& u, RayStats& stats);

}  // namespace sdfreel::light_beams
