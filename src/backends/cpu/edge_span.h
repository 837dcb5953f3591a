#pragma once
// A triangle's three edge functions over a span of SPAN pixel centres of one row at once (four
// double lanes, one AVX register): each lane performs exactly the scalar operations of
// rasterise()'s per-pixel test on the same values, so the coverage and the edge values are the same
// bits, without a branch per pixel and edge.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sdfreel {

constexpr int SPAN = 4;
typedef double D4 __attribute__((vector_size(32)));
typedef int64_t M4 __attribute__((vector_size(32)));  // lane masks: -1 true, 0 false

// The edge values of the pixels of one span.
struct EdgeSpan {
  D4 b[3];
};

// Edge k runs from (ax, ay) by (ex, ey); b_k(p) = ex * (p.y - ay) - ey * (p.x - ax). A centre is
// inside an edge when b > 0, or b == 0 on a left or top edge (the top-left rule): b > 0 or
// b == on_edge[k], which is 0 on such an edge and NaN (equal to nothing) on the others.
struct EdgeRow {
  double ax[3], ay[3], ex[3], ey[3];
  double on_edge[3];
  double row[3];     // ex * (centre_y - ay) of the current row
  double inv_ey[3];  // 1 / ey, for columns() (a bound with a margin: not bits)

  void set_edge(int k, double a_x, double a_y, double c_x, double c_y, bool top_left) {
    ax[k] = a_x, ay[k] = a_y, ex[k] = c_x - a_x, ey[k] = c_y - a_y;
    on_edge[k] = top_left ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    inv_ey[k] = 1.0 / ey[k];
  }

  void start_row(int wy) {
    const double centre_y = wy + 0.5;
    for (int k = 0; k < 3; ++k) row[k] = ex[k] * (centre_y - ay[k]);
  }

  // Narrows [first, last] to the columns of the current row that may hold covered centres: each
  // sloped edge's crossing of the row, widened by a pixel against rounding (cover() still decides
  // every pixel exactly); the rest of the row would cost a span test each. False: none can.
  bool columns(int& first, int& last) const {
    double lo = first, hi = last;
    for (int k = 0; k < 3; ++k) {
      if (ey[k] == 0.0) {  // b = row[k] along the whole row
        if (!(row[k] > 0.0 || row[k] == on_edge[k])) return false;
        continue;
      }
      const double cross = ax[k] + row[k] * inv_ey[k] - 0.5;  // where b crosses 0
      // Far away (or NaN): rounding could exceed the margin, and it cannot narrow a tile anyway.
      if (!(std::abs(cross) < 1e12 && std::abs(ax[k]) < 1e12)) continue;
      if (ey[k] > 0.0)
        hi = std::min(hi, std::floor(cross) + 1.0);  // b falls along the row
      else
        lo = std::max(lo, std::ceil(cross) - 1.0);
    }
    if (lo > hi) return false;
    first = int(lo), last = int(hi);
    return true;
  }

  // The edge values of pixels wx .. wx + SPAN - 1 of the current row into span, and a bit per
  // pixel (up to last) whose centre is inside.
  unsigned cover(int wx, int last, EdgeSpan& span) const {
    const D4 column = double(wx) + D4{0.0, 1.0, 2.0, 3.0};  // exact: integers
    const D4 centre_x = column + 0.5;
    M4 inside = column <= double(last);
    for (int k = 0; k < 3; ++k) {
      const D4 b = row[k] - ey[k] * (centre_x - ax[k]);
      span.b[k] = b;
      inside &= (b > 0.0) | (b == on_edge[k]);
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
