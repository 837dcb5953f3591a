#pragma once
// Frames whose numbers are already display values (a user's Shadertoy shader writes sRGB-encoded
// colour, docs/shaders.md): the display frame is the image itself, clamped and rounded to 16 bits,
// and the linear frame (EXR) its sRGB decoding. No [color] view applies to them.
#include "render/image.h"

namespace sdfreel {

// RGB clamped to [0,1], rounded to 16 bits (alpha dropped).
ImageRGB16 quantised_display(const ImageRGBA& display);
// The sRGB EOTF applied to RGB (clamped below at 0, HDR values above 1 extended), alpha kept.
ImageRGBA srgb_decoded(const ImageRGBA& display);

}  // namespace sdfreel
