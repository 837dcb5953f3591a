#pragma once
// RGBA EXR files (half or float) through OpenEXR itself (not OpenImageIO, whose start-up costs half
// a second: see png_file.h); PIZ files, the default, with their chunks coded by sdfreel on all
// threads and OpenEXR's bytes (io/exr_piz_file.h).
#include <map>
#include <string>
#include <vector>

#include "render/compositing_passes.h"
#include "render/image.h"

namespace sdfreel {

// How an EXR stores its pixels: PIZ-compressed half floats unless [output] says otherwise.
struct ExrSettings {
  std::string compression = "piz";  // none, rle, zips, zip, piz (lossless), dwaa, dwab (lossy)
  bool full_float = false;          // 32-bit float channels instead of half
};
// Whether a compression of exr_compression_names() (timeline/frame_file_options.h) gives the
// pixels back exactly. Throws for another name.
bool exr_compression_is_lossless(const std::string& compression);

// Encodes `linear` as an RGBA EXR in memory, with each metadata entry stored as the string
// attribute "sdfreel:<key>" and the chromaticities of its primaries (Rec.709, D65 white: the
// scene-linear space the scenes render in). Half channels round the floats to nearest even. Each
// compositing pass adds its channels as 32-bit floats (depth, counts: exact beyond half's range).
std::vector<char> encode_exr(const ImageRGBA& linear,
                             const std::map<std::string, std::string>& metadata,
                             const ExrSettings& settings = {},
                             const std::vector<PassImage>& passes = {});

// Reads R, G, B (and A, else 1) of an EXR as floats. Throws std::runtime_error naming `path`.
ImageRGBA read_exr_file(const std::string& path);

// One float channel of an EXR by name (a pass: "samples", "Z", "N.X"...), a value a pixel, rows
// top-down. Throws std::runtime_error naming `path` when it has no such channel.
std::vector<float> read_exr_channel(const std::string& path, const std::string& channel);

// The string attributes of an EXR's header (name -> value), for tests and tools.
std::map<std::string, std::string> read_exr_strings(const std::string& path);

}  // namespace sdfreel
