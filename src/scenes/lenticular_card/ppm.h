#pragma once
// Binary PPM (P6, 8-bit RGB): the cache's file format for source views. Written and read here
// without an image library, so the scenes library stays free of one; any viewer opens it and
// `sdfreel interlace` reads it.
#include <string>

#include "scenes/lenticular_card/interlace.h"

namespace sdfreel::lenticular_card {

// The file's bytes for `img`.
std::string encode_ppm(const Rgb8Image& img);
// False (and img untouched) unless `path` holds a well-formed P6 image with maxval 255.
bool read_ppm(const std::string& path, Rgb8Image& img);

}  // namespace sdfreel::lenticular_card
