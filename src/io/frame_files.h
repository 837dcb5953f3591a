#pragma once
// Frame files (OpenEXR, libpng), written atomically (temporary file in the same folder, then
// rename): a killed render never leaves a truncated frame.
#include <map>
#include <string>
#include <vector>

#include "io/exr_file.h"
#include "render/image.h"

namespace sdfreel {

// EXR: RGBA, scene-linear, half floats and PIZ unless `settings` says otherwise, with string
// metadata attributes (key -> value, stored as "sdfreel:<key>") and compositing passes.
void write_exr_atomic(const std::string& path, const ImageRGBA& linear,
                      const std::map<std::string, std::string>& metadata,
                      const ExrSettings& settings = {}, const std::vector<PassImage>& passes = {});
// PNG: 16-bit RGB display values.
void write_png16_atomic(const std::string& path, const ImageRGB16& display);

// Read back (for --resume, encode, verify). Throw std::runtime_error on failure.
ImageRGB16 read_png16(const std::string& path);
ImageRGBA read_exr(const std::string& path);  // half values widened to float

// Writes a small file atomically (manifest, framemd5).
void write_text_atomic(const std::string& path, const std::string& contents);

}  // namespace sdfreel
