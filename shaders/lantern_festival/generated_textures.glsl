// The generated textures of one seed (src/scenes/lantern_festival/generated_textures.h), as the C++ scene
// hands them over in shader_textures(). Read only through common/texture.glsl.
#include "common/texture.glsl"

uniform sampler2D u_blue_noise;       // RGBA: x, z offset, flicker phase, yaw of each cell
uniform sampler2D u_paper_normal;     // RGB: tangent-space normal * 0.5 + 0.5
uniform sampler2D u_paper_noise;      // R: value noise in [0, 1] (paper blotches, moon maria)
uniform sampler2D u_sky_env;          // RGB equirect night sky
uniform sampler2D u_sky_env_blurred;  // its box-filtered copy, for reflections
