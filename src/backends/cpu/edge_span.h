#pragma once
// A triangle's three edge functions over a span of SPAN pixel centres of one row at once (four
// double lanes, one AVX register): each lane performs exactly the scalar operations of
// rasterise()'s per-pixel test on the same values, so the coverage and the edge values are the same
// bits, without a branch per pixel and edge.
#include <cstdint>

namespace sdfreel {

constexpr int SPAN = 4;
typedef double D4 __attribute__((vector_size(32)));
typedef int64_t M4 __attribute__((vector_size(32)));  // lane masks: -1 true, 0 false

// The edge values of the pixels of one span.
struct EdgeSpan {
  D4 b[3];
};

// Edge k runs from (ax, ay) by (ex, ey); b_k(p) = ex * (p.y - ay) - ey * (p.x - ax). tl: a centre
// exactly on the edge is inside (the top-left rule).
struct EdgeRow {
  double ax[3], ay[3], ex[3], ey[3];
  int64_t tl[3];  // -1: true, 0: false (a lane mask)
  double row[3];  // ex * (centre_y - ay) of the current row

  void start_row(int wy) {
    const double centre_y = wy + 0.5;
    for (int k = 0; k < 3; ++k) row[k] = ex[k] * (centre_y - ay[k]);
  }

  // The edge values of pixels wx .. wx + SPAN - 1 of the current row into span, and a bit per
  // pixel (up to last) whose centre is inside.
  unsigned cover(int wx, int last, EdgeSpan& span) const {
    const D4 centre_x = D4{double(wx), double(wx + 1), double(wx + 2), double(wx + 3)} + 0.5;
    M4 inside = M4{wx <= last, wx + 1 <= last, wx + 2 <= last, wx + 3 <= last} != 0;
    for (int k = 0; k < 3; ++k) {
      const D4 b = row[k] - ey[k] * (centre_x - ax[k]);
      span.b[k] = b;
      inside &= (b > 0.0) | ((b == 0.0) & tl[k]);
    }
#ifdef __AVX__
    return unsigned(__builtin_ia32_movmskpd256(D4(inside)));  // the lanes' sign bits
#else
    unsigned bits = 0;
    for (int j = 0; j < SPAN; ++j) bits |= inside[j] ? 1u << j : 0u;
    return bits;
#endif
  }
};

}  // namespace sdfreel
