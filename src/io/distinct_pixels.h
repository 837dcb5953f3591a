#pragma once
// A per-pixel colour conversion run once per distinct RGB of a buffer, not once per pixel: a
// frame's flat backdrop or black border repeats one value thousands of times (a lenticular card
// frame: 18% of its RGB values distinct, 44% of its pixels equal to their left neighbour), and the
// display transform of a pixel costs about a hundred nanoseconds.
#include <cstddef>

namespace sdfreel {

// Converts the RGB of rgba[0 .. n) in place (alpha kept) as convert(rgba, n) would, when convert's
// RGB result for each pixel is a function of that pixel's RGB alone and it keeps alpha: convert
// runs on the pixels whose RGB bits a small cache of recent values has not seen, and each other
// pixel copies the result of its twin.
using PixelConversion = void (*)(float* rgba, size_t n);
void convert_distinct(float* rgba, size_t n, PixelConversion convert);

}  // namespace sdfreel
