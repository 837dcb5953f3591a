#pragma once
// Cube textures of a user's shader: cubemap channels read from files, and Cube A's output, whose
// faces are drawn with the site's corner rays (docs/shaders.md).
#include <array>
#include <glm/glm.hpp>

#include "backends/gl/gl_api.h"
#include "shader/cube_faces.h"

namespace sdfreel {

// An RGBA32F cube texture of size x size faces, every mip level defined; `faces` (GL's face
// order, row 0 at t = 0) or nothing.
GLuint cube_texture(const GlApi& gl, int size, const CubeFaces* faces);

// The site's corners of cube face `face` (GL's order): the ray through uv (0..1, y up) is
// mix(mix(c[0], c[1], uv.x), mix(c[3], c[2], uv.x), uv.y) - c[4].
const std::array<glm::vec3, 5>& cube_face_corners(int face);

}  // namespace sdfreel
