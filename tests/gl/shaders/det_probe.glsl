// Evaluates one function of common/ per pixel on inputs from a texture, for the bit-for-bit
// comparison with the C++ twins in det_math_test.cpp. Texel (x, row) holds the arguments.
#include "common/noise.glsl"

uniform sampler2D u_inputs;
uniform int u_function;
layout(location = 0) precise out vec4 frag;

vec4 probe(vec4 a) {
  switch (u_function) {
    case 0: return vec4(dm_sin(a.x), dm_cos(a.x), 0.0, 0.0);
    case 1: return vec4(dm_atan2(a.x, a.y), dm_atan(a.x), 0.0, 0.0);
    case 2: return vec4(dm_asin(a.x), dm_acos(a.x), 0.0, 0.0);
    case 3: return vec4(dm_exp(a.x), dm_tanh(a.x), 0.0, 0.0);
    case 4: return vec4(dm_log(a.x), dm_pow(a.x, a.y), 0.0, 0.0);
    case 5: return vec4(value_noise(a.xyz, 7u), value_noise(a.xy, 3u), fbm(a.xyz, 5, 11u),
                        fbm(a.xy, 4, 2u));
    case 6: return vec4(worley(a.xyz, 5u), worley(a.xy, 9u));
    case 7: return vec4(sdTorus(a.xyz, vec2(1.0, 0.25)), sdBox(a.xyz, vec3(0.5, 0.3, 0.2)),
                        sdCappedTorus(a.xyz, vec2(0.8, 0.6), 0.7, 0.1),
                        sdCappedCylinder(a.xyz, 0.4, 0.3));
    case 8: return vec4(opSmoothUnion(a.x, a.y, a.z), opSmoothSubtraction(a.x, a.y, a.z),
                        opSmoothIntersection(a.x, a.y, a.z), sdRoundBox(a.xyz, vec3(0.4), 0.1));
    case 9: return vec4(safe_normalize(a.xyz), dm_smoothstep(-0.5, 0.7, a.w));
    // Hashes as exact floats (24 bits).
    case 10: return vec4(float(pcg_hash(floatBitsToUint(a.x)) >> 8u),
                         vec3(pcg3d(floatBitsToUint(a.xyz)) >> 8u));
    default: return vec4(0.0);
  }
}

void main() {
  int h = textureSize(u_inputs, 0).y;
  ivec2 texel = ivec2(int(gl_FragCoord.x), h - 1 - int(gl_FragCoord.y));
  frag = probe(texelFetch(u_inputs, texel, 0));
}
