#pragma once
// An image file a shader's channel reads (docs/shaders.md), as Shadertoy hands it to a shader:
// an 8- or 16-bit file's codes as code / 255 (65535), decoded from sRGB to linear only when the
// channel asks (`srgb`, as the site's sampler does); a float file (EXR, HDR, float TIFF) as
// stored. Gray files give r = g = b; alpha is the file's, or 1.
#include <string>

#include "io/image_plugin.h"
#include "render/image.h"

namespace sdfreel {

// RGBA floats, row 0 at the top.
ImageRGBA texture_texels(const StoredImage& stored, bool srgb);

// Reads `path` through the image module. Throws InputError naming `path` when it cannot.
ImageRGBA read_texture_file(const std::string& path, bool srgb);

}  // namespace sdfreel
