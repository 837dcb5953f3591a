#pragma once
// Half-float RGBA EXR files through OpenEXR itself (not OpenImageIO, whose start-up costs half a
// second: see png_file.h).
#include <map>
#include <string>
#include <vector>

#include "render/image.h"

namespace sdfreel {

// Encodes `linear` as a PIZ-compressed half RGBA EXR in memory, with each metadata entry stored
// as the string attribute "sdfreel:<key>". The floats are rounded to half (nearest even).
std::vector<char> encode_exr(const ImageRGBA& linear,
                             const std::map<std::string, std::string>& metadata);

// Reads R, G, B (and A, else 1) of an EXR as floats. Throws std::runtime_error naming `path`.
ImageRGBA read_exr_file(const std::string& path);

// The string attributes of an EXR's header (name -> value), for tests and tools.
std::map<std::string, std::string> read_exr_strings(const std::string& path);

}  // namespace sdfreel
