#pragma once
// Hashes: MD5 of packed rgb48le display pixels (FFmpeg framemd5), a hash of the scene-linear
// pixels as stored in EXR (half floats). Both io/md5.h's (SHA-256: timeline/sha256.h).
#include <string>

#include "render/image.h"

namespace sdfreel {

std::string md5_rgb48le(const ImageRGB16& display);     // 32 hex chars, as framemd5 prints
std::string linear_half_hash(const ImageRGBA& linear);  // MD5 of little-endian half RGBA

}  // namespace sdfreel
