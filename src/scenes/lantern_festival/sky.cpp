#include "scenes/lantern_festival/sky.h"

#include <tbb/parallel_for.h>

#include "sdf/lanes_exp_log.h"
#include "sdf/noise.h"
#include "sdf/sdf.h"

namespace sdfreel::lantern_festival {

namespace {

// Night gradient (linear Rec.709): deep blue overhead, a lighter haze at the horizon.
const glm::vec3 SKY_ZENITH(0.0040f, 0.0065f, 0.0180f);
const glm::vec3 SKY_HORIZON(0.0200f, 0.0290f, 0.0520f);
const glm::vec3 SKY_BELOW(0.0080f, 0.0110f, 0.0200f);  // never seen directly: under the fog
// Stars: expected count per steradian-equivalent texel share, and their brightness range.
constexpr float STAR_DENSITY = 0.0040f;
constexpr float STAR_MIN = 0.05f, STAR_RANGE = 1.2f;
const glm::vec3 STAR_COOL(0.80f, 0.88f, 1.00f), STAR_WARM(1.00f, 0.90f, 0.75f);
// Clouds: a thin layer seen in perspective, faint grey-blue, that hides the stars behind it.
constexpr float CLOUD_SCALE = 0.9f;
constexpr float CLOUD_LAYER_BIAS = 0.12f;  // flattens the perspective at the horizon
constexpr float CLOUD_COVER_LO = 0.52f, CLOUD_COVER_HI = 0.78f;
const glm::vec3 CLOUD_COLOR(0.030f, 0.036f, 0.052f);
constexpr int CLOUD_OCTAVES = 4;
// Clouds are soft: computed on a grid this many times coarser per axis, then filtered up.
constexpr int CLOUD_DOWNSAMPLE = 4;
// Moon: disc half-angle (stylised, about four times the real one), halo falloff and strength.
constexpr float MOON_RADIUS_RAD = 0.018f;
constexpr float MOON_EDGE_SOFTNESS = 0.12f;  // share of the radius
constexpr float MOON_DISC_GAIN = 40.0f;      // disc radiance per unit of moonlight
constexpr float MOON_HALO_SHARPNESS = 900.0f, MOON_HALO_GAIN = 0.35f;
constexpr float MOON_GLOW_SHARPNESS = 12.0f, MOON_GLOW_GAIN = 0.05f;
constexpr float MOON_MARIA_DEPTH = 0.35f, MOON_MARIA_SCALE = 0.5f;
// The seed's fog: clamp(mix(1, -1.5, y)), smoothstep, then the 15th power.
constexpr float FOG_MIX_TO = -1.5f;

glm::vec3 equirect_direction(float u, float v) {
  const float phi = u * dm::TWO_PI, theta = v * dm::PI;
  const float s = dm::sin(theta);
  return glm::vec3(s * dm::cos(phi), dm::cos(theta), s * dm::sin(phi));
}

template <class F>
F pow15(F x) {
  const F x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  return x8 * x4 * x2 * x;
}

// Cloud cover in [0, 1] on an equirect grid: a thin layer seen in perspective.
Texture make_cloud_cover(int width, int height, uint32_t seed) {
  Texture t(width, height, 1);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const glm::vec3 dir =
          equirect_direction((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      const float e = dir.y;
      float cover = 0.0f;
      if (e > 0.0f) {
        const glm::vec2 layer = glm::vec2(dir.x, dir.z) / (e + CLOUD_LAYER_BIAS) * CLOUD_SCALE;
        cover = dm::smoothstep(CLOUD_COVER_LO, CLOUD_COVER_HI, fbm(layer, CLOUD_OCTAVES, seed)) *
                dm::smoothstep(0.0f, 0.15f, e);
      }
      *t.at(x, y) = cover;
    }
  });
  return t;
}

}  // namespace

Texture make_sky_environment(int width, int height, uint32_t seed) {
  Texture t(width, height, 3);
  const uint32_t star_seed = pcg_hash(seed ^ 0x5f3759dfu);
  const Texture clouds =
      make_cloud_cover(width / CLOUD_DOWNSAMPLE, height / CLOUD_DOWNSAMPLE, pcg_hash(seed + 31u));
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const float u = (float(x) + 0.5f) / float(width), v = (float(y) + 0.5f) / float(height);
      const glm::vec3 dir = equirect_direction(u, v);
      const float e = dir.y;
      glm::vec3 col;
      if (e > 0.0f) {
        const float h = dm::sqrt(dm::smoothstep(0.0f, 1.0f, e));
        col = dm::mix(SKY_HORIZON, SKY_ZENITH, h);
      } else {
        col = dm::mix(SKY_HORIZON, SKY_BELOW, dm::smoothstep(0.0f, 0.2f, -e));
      }
      const float cover = sampleBilinearEquirect(clouds, glm::vec2(u, v)).x;
      col = dm::mix(col, CLOUD_COLOR, cover);
      // Stars, evenly spread over the sphere: a texel's chance follows its solid angle (sin theta).
      const uint32_t h = hash2i(x, y, star_seed);
      const float sin_theta = dm::sqrt(dm::max(0.0f, 1.0f - e * e));
      if (hash_to_unit(h) < STAR_DENSITY * sin_theta) {
        const float r = hash_to_unit(pcg_hash(h)), r2 = r * r, r6 = r2 * r2 * r2;
        const float b = STAR_MIN + STAR_RANGE * r6;
        const glm::vec3 tint = dm::mix(STAR_COOL, STAR_WARM, hash_to_unit(pcg_hash(h + 1u)));
        col += tint * (b * (1.0f - cover) * dm::smoothstep(0.0f, 0.12f, e));
      }
      float* c = t.at(x, y);
      c[0] = col.x;
      c[1] = col.y;
      c[2] = col.z;
    }
  });
  return t;
}

glm::vec3 direction_from_angles(double elevation_deg, double azimuth_deg) {
  const float el = float(elevation_deg * (3.14159265358979323846 / 180.0));
  const float az = float(azimuth_deg * (3.14159265358979323846 / 180.0));
  const float ce = dm::cos(el);
  return safe_normalize(glm::vec3(ce * dm::sin(az), dm::sin(el), ce * dm::cos(az)));
}

Texture downsample(const Texture& t, int factor) {
  Texture d(t.width / factor, t.height / factor, t.channels);
  const float inv = 1.0f / float(factor * factor);
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x)
      for (int c = 0; c < t.channels; ++c) {
        float sum = 0.0f;
        for (int j = 0; j < factor; ++j)
          for (int i = 0; i < factor; ++i) sum += t.at(x * factor + i, y * factor + j)[c];
        d.at(x, y)[c] = sum * inv;
      }
  return d;
}

SkyFrame make_sky_frame(const Texture& environment, const Texture& environment_blurred,
                        float intensity, const glm::vec3& moon_dir, const glm::vec3& moon_radiance,
                        const glm::vec3& fog_color, float horizon_fog, const Texture& moon_noise) {
  SkyFrame s;
  s.environment = &environment;
  s.environment_blurred = &environment_blurred;
  s.intensity = intensity;
  s.moon_dir = safe_normalize(moon_dir);
  // Disc frame: any basis perpendicular to the moon direction (the moon is never at the zenith
  // exactly; if it were, +Z serves as the reference).
  const glm::vec3 ref =
      dm::abs(s.moon_dir.y) > 0.999f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  s.moon_right = safe_normalize(glm::cross(ref, s.moon_dir));
  s.moon_up = glm::cross(s.moon_dir, s.moon_right);
  s.moon_disc = moon_radiance * MOON_DISC_GAIN;
  s.moon_glow = moon_radiance;
  s.moon_cos_inner = dm::cos(MOON_RADIUS_RAD * (1.0f - MOON_EDGE_SOFTNESS));
  s.moon_cos_outer = dm::cos(MOON_RADIUS_RAD);
  s.fog_color = fog_color;
  s.horizon_fog = horizon_fog;
  s.moon_noise = &moon_noise;
  return s;
}

namespace {

// The disc of the moon, seen at cosine c (> moon_cos_outer) from its centre.
glm::vec3 moonDisc(const SkyFrame& s, const glm::vec3& dir, float c) {
  const float disc = dm::smoothstep(s.moon_cos_outer, s.moon_cos_inner, c);
  // Maria: the paper's blotch map stretched across the disc (one texture period per radius).
  const glm::vec2 q(glm::dot(dir, s.moon_right), glm::dot(dir, s.moon_up));
  const float maria = sampleBilinear(*s.moon_noise, q * (MOON_MARIA_SCALE / MOON_RADIUS_RAD)).x;
  return s.moon_disc * (disc * (1.0f - MOON_MARIA_DEPTH * maria));
}

// Halo: exp(-k (1 - cos)) ~ a Gaussian in the angle; a tight corona plus a wide glow.
template <class F>
F haloStrength(F c) {
  const F one_minus = 1.0f - c;
  return MOON_HALO_GAIN * dm::exp(-MOON_HALO_SHARPNESS * one_minus) +
         MOON_GLOW_GAIN * dm::exp(-MOON_GLOW_SHARPNESS * one_minus);
}

// The seed's fog band at elevation dir_y; band is dm::mix(1, FOG_MIX_TO, dir_y) with its exact
// product 1 * (1 - dir_y) written as what it is, which lanes can take too.
template <class F>
F fogAmount(F dir_y) {
  const F band = (1.0f - dir_y) + FOG_MIX_TO * dir_y;
  return pow15(dm::smoothstep(0.0f, 1.0f, dm::clamp(band, 0.0f, 1.0f)));
}

// sampleBilinearEquirect's red, green and blue in lanes: each lane the scalar's texel indices
// (repeat in x, clamp in y) and weights.
V3x8 sampleEquirect_lanes(const Texture& t, F8 u, F8 v) {
  const F8 x = u * float(t.width) - 0.5f, y = v * float(t.height) - 0.5f;
  const F8 x0 = dm::floor(x), y0 = dm::floor(y);
  const F8 fx = x - x0, fy = y - y0;
  const auto wrap = [](F8 c, int n) {
    const F8 fn = splat(float(n));
    return __builtin_convertvector(c - fn * dm::floor(c / fn), M8);  // wrap_texel
  };
  const float last_row = float(t.height - 1);
  const M8 xa = wrap(x0, t.width), xb = wrap(x0 + 1.0f, t.width);
  const M8 ya = wrap(dm::clamp(y0, 0.0f, last_row), t.height);
  const M8 yb = wrap(dm::clamp(y0 + 1.0f, 0.0f, last_row), t.height);
  F8 rgb[3];
  for (int c = 0; c < 3; ++c) {
    if (c >= t.channels) {
      rgb[c] = splat(0.0f);
      continue;
    }
    const auto fetch = [&](M8 tx, M8 ty) {
      return gather(t.texels.data(), (ty * t.width + tx) * t.channels + c);
    };
    const F8 a = fetch(xa, ya), b = fetch(xb, ya), cc = fetch(xa, yb), d = fetch(xb, yb);
    const F8 top = a * (1.0f - fx) + b * fx, bottom = cc * (1.0f - fx) + d * fx;
    rgb[c] = top * (1.0f - fy) + bottom * fy;  // mix4 of mix4s
  }
  return V3x8(rgb[0], rgb[1], rgb[2]);
}

}  // namespace

glm::vec3 moon(const SkyFrame& s, const glm::vec3& dir) {
  const float c = glm::dot(dir, s.moon_dir);
  glm::vec3 col = s.moon_glow * haloStrength(c);
  if (c > s.moon_cos_outer) col += moonDisc(s, dir, c);
  return col;
}

glm::vec3 skyFrom(const SkyFrame& s, const Texture& environment, glm::vec3 dir) {
  dir = safe_normalize(dir);
  const float fog = fogAmount(dir.y);
  const float thetaa = dm::acos(dir.y);
  const float phii = dm::atan2(dir.z, dir.x);
  const glm::vec4 env =
      sampleBilinearEquirect(environment, glm::vec2(phii / dm::TWO_PI, thetaa / dm::PI));
  const glm::vec3 col = glm::vec3(env) * s.intensity + moon(s, dir);
  return dm::mix(col, s.fog_color, fog * s.horizon_fog);
}

V3x8 skyFrom_lanes(const SkyFrame& s, const Texture& environment, const V3x8& dir_in, M8 m) {
  const V3x8 up(glm::vec3(0.0f, 1.0f, 0.0f));
  const F8 len2 = vdot(dir_in, dir_in);  // safe_normalize, lanes off m looking up
  const M8 unit = m & (len2 > SAFE_NORMALIZE_MIN_LENGTH2);
  const V3x8 dir = select(unit, dir_in / dm::sqrt(select(unit, len2, splat(1.0f))), up);
  const F8 fog = fogAmount(dir.y);
  const F8 thetaa = dm::acos(dir.y), phii = dm::atan2(dir.z, dir.x);
  const V3x8 env = sampleEquirect_lanes(environment, phii / dm::TWO_PI, thetaa / dm::PI);
  const F8 c = vdot(dir, s.moon_dir);
  V3x8 moon_col = s.moon_glow * haloStrength(c);
  const M8 on_disc = m & (c > s.moon_cos_outer);
  if (any(on_disc))
    for (int i = 0; i < LANES; ++i)
      if (lane(on_disc, i)) moon_col.set_lane(i, moon_col.lane(i) + moonDisc(s, dir.lane(i), c[i]));
  const V3x8 col = env * s.intensity + moon_col;
  const F8 a = fog * s.horizon_fog;
  return col * (1.0f - a) + s.fog_color * a;
}

}  // namespace sdfreel::lantern_festival
