// Deterministic float math: a line-for-line twin of src/sdf/det_math.h (namespace dm -> prefix
// dm_). Keep the two files in step: same polynomials, same constants, same order of operations.
//
// GLSL's built-in sin/cos/exp/pow/dot/length/normalize/mix may be lowered differently by each
// driver (llvmpipe evaluates dot(a, a) as x*x + (y*y + z*z), glm as (x*x + y*y) + z*z), so the
// scene code calls these instead. Exactness also needs the compiler to keep the written order,
// without reassociating, factoring, turning x / c into x * (1 / c) or fusing multiply-adds. The
// `precise` qualifier forbids that for everything that feeds a precise variable. The fragment
// output is precise (sample_loop.glsl), but Mesa 22 does not carry that through every inlined
// call with constant arguments (measured: schlick(x, 0.03) lost an ulp), so the rule for all
// shader code is: every local float/vector variable is declared `precise`. Mesa 25 goes further:
// an expression returned directly (`return a.x * b.x + a.y * b.y;`) or passed straight to a call
// is not exact there even when the caller's variable is precise (measured: sdf_morph's torus lost
// an ulp in dm_dot, Mesa 22.3 and 25.0 parted on 2 pixels), so such expressions go through a
// precise local first. It costs nothing measurable on llvmpipe, and tests/osmesa checks these
// functions bit for bit against C++.

const float DM_PI = 3.14159265358979;
const float DM_TWO_PI = 6.28318530717959;
const float DM_HALF_PI = 1.57079632679490;
const float DM_QUARTER_PI = 0.785398163397448;
const float DM_FLT_MAX = 3.40282347e+38;
const float DM_FLT_MIN = 1.17549435e-38;

// ---- GLSL built-ins with exact semantics ----

float dm_min(float a, float b) { return b < a ? b : a; }
float dm_max(float a, float b) { return a < b ? b : a; }
float dm_clamp(float x, float lo, float hi) {
  precise float r_ = dm_min(dm_max(x, lo), hi);
  return r_;
}
float dm_fract(float x) {
  precise float r_ = x - floor(x);
  return r_;
}
float dm_mod(float x, float y) {
  precise float r_ = x - y * floor(x / y);
  return r_;
}
float dm_mix(float x, float y, float a) {
  precise float r_ = x * (1.0 - a) + y * a;
  return r_;
}
float dm_step(float edge, float x) { return x < edge ? 0.0 : 1.0; }
float dm_smoothstep(float e0, float e1, float x) {
  if (e0 == e1) return x < e0 ? 0.0 : 1.0;
  precise float t = dm_clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  precise float r_ = t * t * (3.0 - 2.0 * t);
  return r_;
}
float dm_sign(float x) {
  precise float r_ = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
  return r_;
}

vec3 dm_mix(vec3 x, vec3 y, float a) {
  precise vec3 r_ = x * (1.0 - a) + y * a;
  return r_;
}
vec2 dm_mix(vec2 x, vec2 y, float a) {
  precise vec2 r_ = x * (1.0 - a) + y * a;
  return r_;
}
vec3 dm_clamp(vec3 v, float lo, float hi) {
  precise vec3 r_ = vec3(dm_clamp(v.x, lo, hi), dm_clamp(v.y, lo, hi), dm_clamp(v.z, lo, hi));
  return r_;
}

// glm's vector helpers, in glm's order of operations (glm/detail/func_geometric.inl).
float dm_dot(vec2 a, vec2 b) {
  precise float r = a.x * b.x + a.y * b.y;
  return r;
}
float dm_dot(vec3 a, vec3 b) {
  precise float r = a.x * b.x + a.y * b.y + a.z * b.z;
  return r;
}
float dm_dot(vec4 a, vec4 b) {
  precise float r_ = (a.x * b.x + a.y * b.y) + (a.z * b.z + a.w * b.w);
  return r_;
}
float dm_length(vec2 v) {
  precise float r = sqrt(dm_dot(v, v));
  return r;
}
float dm_length(vec3 v) {
  precise float r = sqrt(dm_dot(v, v));
  return r;
}
// glm::normalize: v * (1 / sqrt(dot(v, v))).
vec3 dm_normalize(vec3 v) {
  precise vec3 r_ = v * (1.0 / sqrt(dm_dot(v, v)));
  return r_;
}
vec3 dm_cross(vec3 x, vec3 y) {
  precise vec3 r_ = vec3(x.y * y.z - y.y * x.z, x.z * y.x - y.z * x.x, x.x * y.y - y.x * x.y);
  return r_;
}
// glm::reflect: I - N * dot(N, I) * 2.
vec3 dm_reflect(vec3 i, vec3 n) {
  precise vec3 r_ = i - n * dm_dot(n, i) * 2.0;
  return r_;
}
// glm::min/max/abs on vectors are per component.
vec3 dm_max(vec3 v, float b) {
  precise vec3 r_ = vec3(dm_max(v.x, b), dm_max(v.y, b), dm_max(v.z, b));
  return r_;
}
vec2 dm_max(vec2 v, float b) {
  precise vec2 r_ = vec2(dm_max(v.x, b), dm_max(v.y, b));
  return r_;
}

uint dm_float_bits(float x) { return floatBitsToUint(x); }
float dm_bits_float(uint u) {
  precise float r_ = uintBitsToFloat(u);
  return r_;
}

// ---- sin, cos ----

const float DM_PIO2_1 = 1.5703125;
const float DM_PIO2_2 = 4.825592041015625e-4;
const float DM_PIO2_3 = 1.2665987014770508e-6;
const float DM_PIO2_4 = 9.920936294705029e-10;
const float DM_TWO_OVER_PI = 0.636619772367581;
const float DM_REDUCED_LIMIT = 1.0;

struct QuadrantReduced {
  float r;
  int quadrant;
};

QuadrantReduced dm_reduce_half_pi(float x) {
  precise float k = floor(x * DM_TWO_OVER_PI + 0.5);
  precise float r = x - k * DM_PIO2_1;
  r = r - k * DM_PIO2_2;
  r = r - k * DM_PIO2_3;
  r = r - k * DM_PIO2_4;
  r = dm_clamp(r, -DM_REDUCED_LIMIT, DM_REDUCED_LIMIT);
  precise float q = k - 4.0 * floor(k * 0.25);
  return QuadrantReduced(r, int(q));
}

float dm_sin_kernel(float r) {
  precise float z = r * r;
  precise float r_ = ((-1.9515295891e-4 * z + 8.3321608736e-3) * z - 1.6666654611e-1) * z * r + r;
  return r_;
}
float dm_cos_kernel(float r) {
  precise float z = r * r;
  precise float y =
      ((2.443315711809948e-5 * z - 1.388731625493765e-3) * z + 4.166664568298827e-2) * z * z;
  y = y - 0.5 * z;
  precise float r_ = y + 1.0;
  return r_;
}

float dm_sin(float x) {
  QuadrantReduced a = dm_reduce_half_pi(x);
  switch (a.quadrant) {
    case 0: { precise float r_ = dm_sin_kernel(a.r); return r_; }
    case 1: { precise float r_ = dm_cos_kernel(a.r); return r_; }
    case 2: { precise float r_ = -dm_sin_kernel(a.r); return r_; }
    default: { precise float r_ = -dm_cos_kernel(a.r); return r_; }
  }
}

float dm_cos(float x) {
  QuadrantReduced a = dm_reduce_half_pi(x);
  switch (a.quadrant) {
    case 0: { precise float r_ = dm_cos_kernel(a.r); return r_; }
    case 1: { precise float r_ = -dm_sin_kernel(a.r); return r_; }
    case 2: { precise float r_ = -dm_cos_kernel(a.r); return r_; }
    default: { precise float r_ = dm_sin_kernel(a.r); return r_; }
  }
}

// ---- atan, atan2, asin, acos ----

const float DM_TAN_PI_8 = 0.414213562373095;

float dm_atan_unit(float t) {
  precise float base = 0.0;
  if (t > DM_TAN_PI_8) {
    base = DM_QUARTER_PI;
    t = (t - 1.0) / (t + 1.0);
  }
  precise float z = t * t;
  return base +
         ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z -
           3.33329491539e-1) * z * t + t);
}

float dm_atan(float x) {
  precise float a = abs(x);
  precise float r = a > 1.0 ? DM_HALF_PI - dm_atan_unit(1.0 / a) : dm_atan_unit(a);
  precise float r_ = x < 0.0 ? -r : r;
  return r_;
}

float dm_atan2(float y, float x) {
  precise float ax = abs(x), ay = abs(y);
  precise float hi = dm_max(ax, ay), lo = dm_min(ax, ay);
  if (hi == 0.0) return 0.0;
  precise float a = dm_atan_unit(lo / hi);
  if (ay > ax) a = DM_HALF_PI - a;
  if (x < 0.0) a = DM_PI - a;
  precise float r_ = y < 0.0 ? -a : a;
  return r_;
}

float dm_asin_kernel(float s) {
  precise float z = s * s;
  return ((((4.2163199048e-2 * z + 2.4181311049e-2) * z + 4.5470025998e-2) * z +
           7.4953002686e-2) * z + 1.6666752422e-1) * z * s + s;
}

float dm_asin(float x) {
  x = dm_clamp(x, -1.0, 1.0);
  precise float a = abs(x);
  precise float r =
      a > 0.5 ? DM_HALF_PI - 2.0 * dm_asin_kernel(sqrt(0.5 * (1.0 - a))) : dm_asin_kernel(a);
  precise float r_ = x < 0.0 ? -r : r;
  return r_;
}

float dm_acos(float x) {
  x = dm_clamp(x, -1.0, 1.0);
  if (x < -0.5) {
    precise float r_ = DM_PI - 2.0 * dm_asin_kernel(sqrt(0.5 * (1.0 + x)));
    return r_;
  }
  if (x > 0.5) { precise float r_ = 2.0 * dm_asin_kernel(sqrt(0.5 * (1.0 - x))); return r_; }
  precise float r_ = DM_HALF_PI - dm_asin_kernel(abs(x)) * dm_sign(x);
  return r_;
}

// ---- exp, log, pow, tanh ----

const float DM_LOG2E = 1.44269504088896;
const float DM_LN2_HI = 0.693359375;
const float DM_LN2_LO = -2.12194440e-4;
const float DM_EXP_MIN_ARG = -87.3365448;
const float DM_EXP_MAX_ARG = 88.7228;
const float DM_SQRT_HALF = 0.707106781186548;
const float DM_LOG_OF_ZERO = -DM_FLT_MAX;
const float DM_POW_ZERO_NEGATIVE = DM_FLT_MAX;

float dm_exp2_int(int k) {
  precise float r_ = dm_bits_float(uint(k + 127) << 23u);
  return r_;
}

float dm_exp(float x) {
  if (x < DM_EXP_MIN_ARG) return 0.0;
  x = dm_min(x, DM_EXP_MAX_ARG);
  precise float k = floor(x * DM_LOG2E + 0.5);
  precise float r = x - k * DM_LN2_HI;
  r = r - k * DM_LN2_LO;
  precise float z = r * r;
  precise float p = (((((1.9875691500e-4 * r + 1.3981999507e-3) * r + 8.3334519073e-3) * r +
               4.1665795894e-2) * r + 1.6666665459e-1) * r + 5.0000001201e-1) * z + r + 1.0;
  precise float k1 = floor(k * 0.5);
  precise float r_ = p * dm_exp2_int(int(k1)) * dm_exp2_int(int(k - k1));
  return r_;
}

const float DM_TWO_POW_23 = 8388608.0;

float dm_log(float x) {
  if (!(x > 0.0)) return DM_LOG_OF_ZERO;
  x = dm_min(x, DM_FLT_MAX);
  int e = 0;
  if (x < DM_FLT_MIN) {
    x = x * DM_TWO_POW_23;
    e = -23;
  }
  uint bits = dm_float_bits(x);
  e += int((bits >> 23u) & 0xffu) - 126;
  precise float m = dm_bits_float((bits & 0x007fffffu) | 0x3f000000u);
  if (m < DM_SQRT_HALF) {
    e -= 1;
    m = m + m - 1.0;
  } else {
    m = m - 1.0;
  }
  precise float z = m * m;
  precise float y = ((((((((7.0376836292e-2 * m - 1.1514610310e-1) * m + 1.1676998740e-1) * m -
                  1.2420140846e-1) * m + 1.4249322787e-1) * m - 1.6668057665e-1) * m +
               2.0000714765e-1) * m - 2.4999993993e-1) * m + 3.3333331174e-1) * m * z;
  precise float fe = float(e);
  y = y + DM_LN2_LO * fe;
  y = y - 0.5 * z;
  precise float r = m + y;
  r = r + DM_LN2_HI * fe;
  return r;
}

float dm_pow(float x, float y) {
  if (x <= 0.0) {
    if (y > 0.0) return 0.0;
    return y == 0.0 ? 1.0 : DM_POW_ZERO_NEGATIVE;
  }
  precise float r_ = dm_exp(y * dm_log(x));
  return r_;
}

const float DM_TANH_POLY_LIMIT = 0.625;

float dm_tanh(float x) {
  precise float a = abs(x);
  precise float r;
  if (a > DM_TANH_POLY_LIMIT) {
    r = 1.0 - 2.0 / (dm_exp(a + a) + 1.0);
  } else {
    precise float z = x * x;
    r = ((((-5.70498872745e-3 * z + 2.06390887954e-2) * z - 5.37397155531e-2) * z +
          1.33314422036e-1) * z - 3.33332819422e-1) * z * a + a;
  }
  precise float r_ = x < 0.0 ? -r : r;
  return r_;
}
