// Texture reads shared by the scenes: the twin of src/scenes/common/texture.h. The
// driver uploads every texture with nearest filtering; wrapping and bilinear filtering are done
// here with texelFetch and the C++ arithmetic, so both backends filter the same texels the same
// way.
#include "common/det_math.glsl"

// x mod n for integral floats, in [0, n): GLSL's mod() written out as in dm::mod.
int wrap_texel(float x, int n) {
  precise float m = dm_mod(x, float(n));
  return int(m);
}

// texelFetch on a repeating texture; missing channels read as 0 (alpha as 1), like the C++.
vec4 texelFetchRepeat(sampler2D t, float x, float y) {
  ivec2 size = textureSize(t, 0);
  return texelFetch(t, ivec2(wrap_texel(x, size.x), wrap_texel(y, size.y)), 0);
}

// Repeating in x, clamped in y (equirect maps).
vec4 texelFetchRepeatClamp(sampler2D t, float x, float y) {
  ivec2 size = textureSize(t, 0);
  return texelFetchRepeat(t, x, dm_clamp(y, 0.0, float(size.y - 1)));
}

vec4 mix4(vec4 a, vec4 b, float f) {
  precise vec4 r = a * (1.0 - f) + b * f;
  return r;
}

// GL_LINEAR at uv (texel centres at (i + 0.5) / size), GL_REPEAT in both directions.
vec4 sampleBilinear(sampler2D t, vec2 uv) {
  ivec2 size = textureSize(t, 0);
  precise float x = uv.x * float(size.x) - 0.5, y = uv.y * float(size.y) - 0.5;
  precise float x0 = floor(x), y0 = floor(y);
  precise float fx = x - x0, fy = y - y0;
  precise vec4 a = texelFetchRepeat(t, x0, y0), b = texelFetchRepeat(t, x0 + 1.0, y0);
  precise vec4 c = texelFetchRepeat(t, x0, y0 + 1.0), d = texelFetchRepeat(t, x0 + 1.0, y0 + 1.0);
  precise vec4 r = mix4(mix4(a, b, fx), mix4(c, d, fx), fy);
  return r;
}

// GL_LINEAR, GL_REPEAT in u and GL_CLAMP_TO_EDGE in v (equirect environment).
vec4 sampleBilinearEquirect(sampler2D t, vec2 uv) {
  ivec2 size = textureSize(t, 0);
  precise float x = uv.x * float(size.x) - 0.5, y = uv.y * float(size.y) - 0.5;
  precise float x0 = floor(x), y0 = floor(y);
  precise float fx = x - x0, fy = y - y0;
  precise vec4 a = texelFetchRepeatClamp(t, x0, y0), b = texelFetchRepeatClamp(t, x0 + 1.0, y0);
  precise vec4 c = texelFetchRepeatClamp(t, x0, y0 + 1.0);
  precise vec4 d = texelFetchRepeatClamp(t, x0 + 1.0, y0 + 1.0);
  precise vec4 r = mix4(mix4(a, b, fx), mix4(c, d, fx), fy);
  return r;
}
