#pragma once
// The EXR stores half floats, and the display image is made from those same half values, so a
// frame file on disk fully determines both hashes (resume and encode can re-derive them).
#include <optional>
#include <string>

#include "render/image.h"

namespace sdfreel {

// Position of the first NaN or infinite value, as "(x, y) channel c is nan".
std::optional<std::string> find_non_finite(const ImageRGBA& img);
// Sets every NaN or infinite value to 0 (black, as a screen shows it) and returns how many there
// were; *first (when given and any were found) gets the first's description as above.
size_t zero_non_finite(ImageRGBA& img, std::string* first);
// Clamps to [0, 65504] (half's largest finite value) and rounds every value to half precision.
void round_to_half(ImageRGBA& img);

}  // namespace sdfreel
