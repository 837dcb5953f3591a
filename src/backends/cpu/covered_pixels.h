#pragma once
// A triangle's covered pixel centres over part of a tile, packed before any per-pixel work. The
// coverage test runs span by span (edge_span.h) and appends only the covered pixels' edge values,
// without a branch per pixel; the depth and weight divisions then run on full groups of four
// instead of on spans (the fur's are a third empty on average), and the per-pixel loops that
// follow have no coverage branches to mispredict. Each lane performs the scalar operations of one
// pixel on the same values wherever it is packed: the same bits.
#ifdef __AVX2__
#include <immintrin.h>
#endif

#include "backends/cpu/edge_span.h"
#include "sdf/lanes.h"

namespace sdfreel {

#ifdef __AVX2__
// For each set of covered lanes (a 4-bit mask): the lanes in order, first in the vector, as dword
// indices for a permute of four doubles, and as lane numbers.
struct PackOrder {
  alignas(32) int32_t dwords[16][8];
  alignas(16) int32_t lanes[16][4];
  constexpr PackOrder() : dwords(), lanes() {
    for (int mask = 0; mask < 16; ++mask) {
      int n = 0;
      for (int j = 0; j < SPAN; ++j)
        if (mask & (1 << j)) {
          dwords[mask][2 * n] = 2 * j, dwords[mask][2 * n + 1] = 2 * j + 1;
          lanes[mask][n++] = j;
        }
    }
  }
};
inline constexpr PackOrder PACK_ORDER{};
#endif

// What the weights of a triangle's pixels are computed from (rasterise()'s per-triangle values).
struct TriangleWeights {
  double area, depth[3], inv_w[3];
};

struct CoveredPixels {
  static constexpr int CAPACITY = 256;           // pixels in one chunk
  static constexpr int SIZE = CAPACITY + LANES;  // room for a last group of eight
  int count = 0;
  alignas(32) double b[3][SIZE];          // edge values
  alignas(32) int at[SIZE];               // the pixel's index in the image (row * width + column)
  alignas(32) float z[SIZE], w[3][SIZE];  // by weigh()

  // Whether the next span might not fit: draw the chunk first.
  bool full() const { return count > CAPACITY - SPAN; }

  // Appends the pixels of span (image pixels first .. first + SPAN - 1 of one row) whose bit is set
  // in `covered`.
  void append(const EdgeSpan& span, unsigned covered, int first) {
#ifdef __AVX2__
    // Whole vectors written at `count`: the lanes past the covered ones are overwritten next.
    const __m256i order =
        _mm256_load_si256(reinterpret_cast<const __m256i*>(PACK_ORDER.dwords[covered]));
    for (int k = 0; k < 3; ++k)
      _mm256_storeu_pd(b[k] + count, _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(
                                         _mm256_castpd_si256(__m256d(span.b[k])), order)));
    const __m128i lanes =
        _mm_load_si128(reinterpret_cast<const __m128i*>(PACK_ORDER.lanes[covered]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at + count),
                     _mm_add_epi32(_mm_set1_epi32(first), lanes));
    count += __builtin_popcount(covered);
#else
    for (int j = 0; j < SPAN; ++j) {
      for (int k = 0; k < 3; ++k) b[k][count] = span.b[k][j];
      at[count] = first + j;
      count += int((covered >> j) & 1u);
    }
#endif
  }

  // Each pixel's window depth and perspective-correct varying weights: barycentrics l_k = b_k /
  // area, depth sum_k l_k depth_k, q_k = l_k * (1 / w_k) and weights q_k / (q_0 + q_1 + q_2).
  // The places up to the next multiple of LANES repeat the first pixel (a valid one), so groups
  // of eight read only finite values and pixels of the frame.
  void weigh(const TriangleWeights& t);
};

}  // namespace sdfreel
