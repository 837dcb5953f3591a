#pragma once
// OpenEXR's 2D Haar wavelet of PIZ (wav2Encode), in place: each level turns 2x2 blocks of
// 16-bit values into an average and three differences. 14-bit arithmetic when every value is below
// 1 << 14 (the smaller differences code best), else modulo 1 << 16, as OpenEXR decides.
#include <cstdint>

namespace sdfreel {

// values[x * ox + y * oy] for x < nx, y < ny; `max` the largest value.
void exr_wavelet_encode(uint16_t* values, int nx, int ox, int ny, int oy, uint16_t max);

}  // namespace sdfreel
