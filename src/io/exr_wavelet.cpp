#include "io/exr_wavelet.h"

namespace sdfreel {

namespace {

// The average and difference of a pair as signed 16-bit values.
struct Pair14 {
  static void encode(uint16_t a, uint16_t b, uint16_t& l, uint16_t& h) {
    const int16_t as = int16_t(a), bs = int16_t(b);
    l = uint16_t(int16_t((as + bs) >> 1));
    h = uint16_t(int16_t(as - bs));
  }
};

// The same modulo 1 << 16, for values of any 16 bits.
struct Pair16 {
  static void encode(uint16_t a, uint16_t b, uint16_t& l, uint16_t& h) {
    constexpr int OFFSET = 1 << 15, MASK = 0xffff;
    const int ao = (a + OFFSET) & MASK;
    int m = (ao + b) >> 1;
    int d = ao - b;
    if (d < 0) m = (m + OFFSET) & MASK;
    d &= MASK;
    l = uint16_t(m);
    h = uint16_t(d);
  }
};

// Offsets, not pointers, walk the rows: the last step of each loop lies past the values.
template <class P>
void encode_levels(uint16_t* in, int nx, int ox, int ny, int oy) {
  const int n = nx > ny ? ny : nx;
  for (int p = 1, p2 = 2; p2 <= n; p = p2, p2 <<= 1) {
    const long ey = long(oy) * (ny - p2), ex = long(ox) * (nx - p2);
    const long oy1 = long(oy) * p, oy2 = long(oy) * p2, ox1 = long(ox) * p, ox2 = long(ox) * p2;
    uint16_t i00, i01, i10, i11;
    long y = 0;
    for (; y <= ey; y += oy2) {
      long x = y;
      for (; x <= y + ex; x += ox2) {
        uint16_t *px = in + x, *p01 = px + ox1, *p10 = px + oy1, *p11 = p10 + ox1;
        P::encode(*px, *p01, i00, i01);
        P::encode(*p10, *p11, i10, i11);
        P::encode(i00, i10, *px, *p10);
        P::encode(i01, i11, *p01, *p11);
      }
      if (nx & p) {  // a last column without a partner: pairs down only
        uint16_t *px = in + x, *p10 = px + oy1;
        P::encode(*px, *p10, i00, *p10);
        *px = i00;
      }
    }
    if (ny & p) {  // a last row without a partner: pairs across only
      for (long x = y; x <= y + ex; x += ox2) {
        uint16_t *px = in + x, *p01 = px + ox1;
        P::encode(*px, *p01, i00, *p01);
        *px = i00;
      }
    }
  }
}

}  // namespace

void exr_wavelet_encode(uint16_t* values, int nx, int ox, int ny, int oy, uint16_t max) {
  if (max < (1 << 14))
    encode_levels<Pair14>(values, nx, ox, ny, oy);
  else
    encode_levels<Pair16>(values, nx, ox, ny, oy);
}

}  // namespace sdfreel
