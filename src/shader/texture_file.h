#pragma once
// An image file a shader's channel reads (docs/shaders.md): PNG (8 or 16 bits, taken as the
// sRGB-encoded numbers Shadertoy hands a shader, 0..1) or EXR (float, kept float).
#include <string>

#include "render/image.h"

namespace sdfreel {

// RGBA floats, row 0 at the top. Throws InputError naming `path` when it cannot be decoded.
ImageRGBA read_texture_file(const std::string& path);

}  // namespace sdfreel
