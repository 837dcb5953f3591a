#include "render/passes/crepuscular_rays_rows.h"

#include <algorithm>
#include <cmath>

#include "sdf/det_math.h"
#include "sdf/lanes.h"
#include "sdf/noise.h"

namespace sdfreel {
namespace {

// The texels of the occlusion image that are not +0, as a box of pixel indices (empty: lo > hi).
// A tap of +0 outside it adds +0 * decay_acc * weight = +0 to c, which leaves c unchanged while
// c is not -0: so the box is used only when no texel is negative or -0 (c then starts at or above
// +0 and only grows), the weight is finite and at least 0 and decay lies in [0, 1] (decay_acc stays
// finite). Otherwise the box is the whole image, which skips nothing.
struct LitBox {
  int lo_x, hi_x, lo_y, hi_y;
};

LitBox lit_box(const CrepuscularRays& r, const ImageRGBA& occ) {
  const LitBox all{0, occ.width - 1, 0, occ.height - 1};
  if (!(r.weight >= 0.0f && r.weight <= 3.4e38f && r.decay >= 0.0f && r.decay <= 1.0f)) return all;
  LitBox b{occ.width, -1, occ.height, -1};
  for (int y = 0; y < occ.height; ++y)
    for (int x = 0; x < occ.width; ++x) {
      const float v = occ.at(x, y)[0];
      if (std::signbit(v)) return all;
      if (v != 0.0f) {
        b.lo_x = std::min(b.lo_x, x), b.hi_x = std::max(b.hi_x, x);
        b.lo_y = std::min(b.lo_y, y), b.hi_y = std::max(b.hi_y, y);
      }
    }
  return b;
}

M8 splat_int(int v) {
  return M8{v, v, v, v, v, v, v, v};
}

// Channel 0 of the texels at pixel indices (x, y), lanes off `live` reading texel 0.
F8 gather_occlusion(const ImageRGBA& occ, M8 x, M8 y, M8 live) {
  const M8 index = live ? (y * occ.width + x) * 4 : splat_int(0);
#ifdef __AVX2__
  return reinterpret_cast<F8>(
      _mm256_i32gather_ps(occ.pixels.data(), reinterpret_cast<__m256i>(index), 4));
#else
  F8 v;
  for (int i = 0; i < LANES; ++i) v[i] = occ.pixels[size_t(index[i])];
  return v;
#endif
}

// occlusion_at's texel indices, floor(uv * size) clamped to the last texel; lanes off `live` get
// uv 0 first (their uv may be anywhere, and float-to-int of a huge value is undefined).
void texel_of(const ImageRGBA& occ, F8 u, F8 v, M8 live, M8& x, M8& y) {
  u = select(live, u, splat(0.0f));
  v = select(live, v, splat(0.0f));
  x = __builtin_convertvector(dm::floor(u * float(occ.width)), M8);
  y = __builtin_convertvector(dm::floor(v * float(occ.height)), M8);
  x = x < occ.width ? x : splat_int(occ.width - 1);
  y = y < occ.height ? y : splat_int(occ.height - 1);
}

struct Packet {
  F8 u, v;  // after the jitter
  F8 du, dv;
  F8 c;  // the pixel's own tap, weighted
};

// The tap loop of crepuscular_rays_pixel for eight pixels. Each lane runs the scalar loop's
// operations in its order: uv -= delta; stop when outside; c += occ(uv) * decay_acc * weight;
// decay_acc *= decay. A lane's texel indices move monotonically (delta is fixed), so once every
// live lane has passed the lit box in the direction it moves, every later tap is 0 and the loop
// may stop; taps of a packet wholly outside the box skip the read.
F8 march(const CrepuscularRays& r, const ImageRGBA& occ, const LitBox& box, Packet p) {
  if (box.lo_x > box.hi_x) return p.c;
  const M8 left = p.du > 0.0f, right = p.du<0.0f, up = p.dv> 0.0f, down = p.dv < 0.0f;
  M8 live = splat_mask(true);
  float decay_acc = r.decay;
  for (int i = 1; i < r.samples; ++i) {
    p.u = p.u - p.du;
    p.v = p.v - p.dv;
    live &= ~((p.u < 0.0f) | (p.u > 1.0f) | (p.v < 0.0f) | (p.v > 1.0f));
    M8 x, y;
    texel_of(occ, p.u, p.v, live, x, y);
    const M8 past = (left & (x < box.lo_x)) | (right & (x > box.hi_x)) | (up & (y < box.lo_y)) |
                    (down & (y > box.hi_y));
    live &= ~past;
    if (!any(live)) break;
    const M8 in_box = live & (x >= box.lo_x) & (x <= box.hi_x) & (y >= box.lo_y) & (y <= box.hi_y);
    if (any(in_box)) {
      const F8 tap = gather_occlusion(occ, x, y, in_box);
      p.c = select(in_box, p.c + tap * decay_acc * r.weight, p.c);
    }
    decay_acc = decay_acc * r.decay;
  }
  return p.c;
}

}  // namespace

ImagePass::RowFunction crepuscular_rays_rows(const CrepuscularRays& r, const ImageRGBA& occ) {
  const LitBox box = r.fade > 0.0f ? lit_box(r, occ) : LitBox{0, -1, 0, -1};
  return [r, &occ, box](int y, int x0, int x1, float* out) {
    for (int x = x0; x < x1; x += LANES) {
      const int n = std::min(LANES, x1 - x);
      F8 v = splat(0.0f);
      if (r.fade > 0.0f) {
        Packet p;
        F8 px, jitter;
        for (int i = 0; i < LANES; ++i) {
          const int xi = x + std::min(i, n - 1);  // the row's last pixel again past its end
          px[i] = float(xi);
          jitter[i] = hash_to_unit(hash2i(xi, y, r.jitter_seed));
        }
        p.u = (px + 0.5f) / float(occ.width);
        const float v0 = (float(y) + 0.5f) / float(occ.height);
        p.v = splat(v0);
        const float s = r.density / float(r.samples);
        p.du = (p.u - r.light_uv.x) * s;
        p.dv = splat((v0 - r.light_uv.y) * s);
        M8 tx, ty;
        texel_of(occ, p.u, p.v, splat_mask(true), tx, ty);
        p.c = gather_occlusion(occ, tx, ty, splat_mask(true)) * r.weight;
        p.u = p.u - p.du * jitter;
        p.v = p.v - p.dv * jitter;
        v = march(r, occ, box, p) * r.exposure * r.fade;
      }
      for (int i = 0; i < n; ++i) {
        float* o = out + 4 * (x - x0 + i);
        o[0] = o[1] = o[2] = v[i];
        o[3] = 1.0f;
      }
    }
  };
}

}  // namespace sdfreel
