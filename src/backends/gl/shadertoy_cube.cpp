#include "backends/gl/shadertoy_cube.h"

namespace sdfreel {

GLuint cube_texture(const GlApi& gl, int size, const CubeFaces* faces) {
  GLuint t = 0;
  gl.GenTextures(1, &t);
  gl.BindTexture(GL_TEXTURE_CUBE_MAP, t);
  for (int f = 0; f < 6; ++f)
    gl.TexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA32F, size, size, 0, GL_RGBA,
                  GL_FLOAT, faces ? faces->faces[size_t(f)].pixels.data() : nullptr);
  gl.GenerateMipmap(GL_TEXTURE_CUBE_MAP);
  return t;
}

const std::array<glm::vec3, 5>& cube_face_corners(int face) {
  static const std::array<std::array<glm::vec3, 5>, 6> corners = {{
      {{{1, 1, 1}, {1, 1, -1}, {1, -1, -1}, {1, -1, 1}, {0, 0, 0}}},      // +x
      {{{-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}, {-1, -1, -1}, {0, 0, 0}}},  // -x
      {{{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, {0, 0, 0}}},      // +y
      {{{-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}, {0, 0, 0}}},  // -y
      {{{-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1}, {0, 0, 0}}},      // +z
      {{{1, 1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}, {0, 0, 0}}},  // -z
  }};
  return corners[size_t(face)];
}

}  // namespace sdfreel
