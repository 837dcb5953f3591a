#pragma once
// Float textures a scene generates (lantern_festival: blue noise, paper maps, sky) and the only
// ways scenes read them: texelFetch with wrapped coordinates, and bilinear filtering written out by
// hand, so that the GLSL twin (texelFetch + the same arithmetic) filters exactly like the C++ path.
#include <glm/glm.hpp>
#include <vector>

#include "sdf/det_math.h"

namespace sdfreel {

struct Texture {
  int width = 0, height = 0, channels = 4;
  std::vector<float> texels;  // width * height * channels, row-major, row 0 first

  Texture() = default;
  Texture(int w, int h, int c)
      : width(w), height(h), channels(c), texels(size_t(w) * h * c, 0.0f) {}
  float* at(int x, int y) { return &texels[(size_t(y) * width + x) * channels]; }
  const float* at(int x, int y) const { return &texels[(size_t(y) * width + x) * channels]; }
};

// x mod n for integral floats (exact below 2^24), in [0, n): GLSL's mod(), never C++'s % on
// negatives. Coordinates outside +-2^24 texels are not used by the scene.
inline int wrap_texel(float x, int n) {
  return int(dm::mod(x, float(n)));
}

// texelFetch on a repeating texture; missing channels read as 0 (alpha as 1), like GL.
inline glm::vec4 texelFetchRepeat(const Texture& t, float x, float y) {
  const float* c = t.at(wrap_texel(x, t.width), wrap_texel(y, t.height));
  glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
  for (int i = 0; i < t.channels && i < 4; ++i) v[i] = c[i];
  return v;
}

// texelFetch repeating in x, clamped in y (equirect maps: longitude wraps, latitude stops at the
// poles).
inline glm::vec4 texelFetchRepeatClamp(const Texture& t, float x, float y) {
  return texelFetchRepeat(t, x, dm::clamp(y, 0.0f, float(t.height - 1)));
}

inline glm::vec4 mix4(const glm::vec4& a, const glm::vec4& b, float f) {
  return a * (1.0f - f) + b * f;
}

// GL_LINEAR at uv (texel centres at (i + 0.5) / size), GL_REPEAT in both directions.
inline glm::vec4 sampleBilinear(const Texture& t, const glm::vec2& uv) {
  const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
  const float x0 = dm::floor(x), y0 = dm::floor(y);
  const float fx = x - x0, fy = y - y0;
  const glm::vec4 a = texelFetchRepeat(t, x0, y0), b = texelFetchRepeat(t, x0 + 1.0f, y0);
  const glm::vec4 c = texelFetchRepeat(t, x0, y0 + 1.0f),
                  d = texelFetchRepeat(t, x0 + 1.0f, y0 + 1.0f);
  return mix4(mix4(a, b, fx), mix4(c, d, fx), fy);
}

// GL_LINEAR, GL_REPEAT in u and GL_CLAMP_TO_EDGE in v (equirect environment).
inline glm::vec4 sampleBilinearEquirect(const Texture& t, const glm::vec2& uv) {
  const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
  const float x0 = dm::floor(x), y0 = dm::floor(y);
  const float fx = x - x0, fy = y - y0;
  const glm::vec4 a = texelFetchRepeatClamp(t, x0, y0), b = texelFetchRepeatClamp(t, x0 + 1.0f, y0);
  const glm::vec4 c = texelFetchRepeatClamp(t, x0, y0 + 1.0f);
  const glm::vec4 d = texelFetchRepeatClamp(t, x0 + 1.0f, y0 + 1.0f);
  return mix4(mix4(a, b, fx), mix4(c, d, fx), fy);
}

}  // namespace sdfreel
