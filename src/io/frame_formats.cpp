#include "io/frame_formats.h"

#include <cstdlib>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/frame_files.h"
#include "io/image_plugin.h"
#include "timeline/timeline.h"

namespace sdfreel {

namespace {

// OpenImageIO's DPX writer keeps the top bits of each 16-bit value (truncation: up to a whole
// 10-bit step darker). Rounded here to the nearest code, held as the 16-bit value whose top bits
// are that code (bits repeated below, as a reader widens it back).
ImageRGB16 rounded_to_bits(const ImageRGB16& display, int bits) {
  ImageRGB16 out = display;
  const uint32_t top = (1u << bits) - 1;
  for (uint16_t& v : out.pixels) {
    const uint32_t code = (uint32_t(v) * top + 32767) / 65535;
    v = uint16_t((code << (16 - bits)) | (code >> (2 * bits - 16)));
  }
  return out;
}

}  // namespace

FrameFormat frame_format(const std::string& ext, const FrameFileOptions& options) {
  FrameFormat f;
  f.ext = ext;
  if (ext == "exr") {
    f.linear = true;
    f.through_oiio = false;
    f.exr = {options.exr_compression, options.exr_bits == 32};
    f.file_bits = options.exr_bits;
    f.exact = exr_compression_is_lossless(options.exr_compression);
  } else if (ext == "png") {
    f.exact = true;
    f.through_oiio = false;
  } else if (ext == "tif" || ext == "tiff") {
    f.file_bits = options.tiff_bits;
    f.linear = f.file_bits == 32;
    f.exact = f.file_bits >= 16;
  } else if (ext == "dpx") {
    f.file_bits = options.dpx_bits;
    f.exact = f.file_bits == 16;
  } else if (ext == "jpg" || ext == "jpeg") {
    f.file_bits = 8;
    f.quality = options.jpeg_quality;
  }
  // Any other extension: 16-bit display values, which OpenImageIO narrows to what the format
  // holds; not taken as exact, since the format may have narrowed them.
  return f;
}

std::vector<std::string> timeline_frame_files(const Timeline& tl) {
  std::vector<std::string> exts;
  if (tl.write_exr) exts.push_back("exr");
  if (tl.write_png) exts.push_back("png");
  for (const Timeline::OtherFrames& o : tl.other_frames) exts.push_back(o.ext);
  return exts;
}

std::map<std::string, std::string> frame_option_values(const std::vector<std::string>& exts,
                                                       const FrameFileOptions& options) {
  const FrameFileOptions defaults;
  std::map<std::string, std::string> values;
  for (const std::string& ext : exts) {
    if (ext == "tif" || ext == "tiff") values["tiff_bits"] = std::to_string(options.tiff_bits);
    if (ext == "dpx") values["dpx_bits"] = std::to_string(options.dpx_bits);
    if (ext == "jpg" || ext == "jpeg")
      values["jpeg_quality"] = std::to_string(options.jpeg_quality);
    if (ext == "exr" && (options.exr_compression != defaults.exr_compression ||
                         options.exr_bits != defaults.exr_bits)) {
      values["exr_compression"] = options.exr_compression;
      values["exr_bits"] = std::to_string(options.exr_bits);
    }
    if (ext == "exr" && !options.passes.empty()) {
      std::string names;
      for (const std::string& p : options.passes) names += (names.empty() ? "" : ",") + p;
      values["passes"] = names;
    }
  }
  return values;
}

FrameFileOptions frame_options_from_values(const std::map<std::string, std::string>& values) {
  FrameFileOptions options;
  auto number = [&](const char* key, int& field) {
    if (auto it = values.find(key); it != values.end()) field = std::atoi(it->second.c_str());
  };
  number("tiff_bits", options.tiff_bits);
  number("dpx_bits", options.dpx_bits);
  number("jpeg_quality", options.jpeg_quality);
  number("exr_bits", options.exr_bits);
  if (auto it = values.find("exr_compression"); it != values.end())
    options.exr_compression = it->second;
  return options;
}

void write_frame_file(const std::string& path, const FrameFormat& format, const ImageRGBA& linear,
                      const ImageRGB16& display, const std::map<std::string, std::string>& metadata,
                      const std::vector<PassImage>& passes) {
  if (!format.through_oiio) {
    if (format.linear)
      write_exr_atomic(path, linear, metadata, format.exr, passes);
    else
      write_png16_atomic(path, display);
    return;
  }
  ImageToWrite image;
  ImageRGB16 rounded;
  if (format.linear) {
    image = {linear.width, linear.height, 4, 32, linear.pixels.data()};
  } else if (format.file_bits == 10 || format.file_bits == 12) {
    rounded = rounded_to_bits(display, format.file_bits);
    image = {display.width, display.height, 3, 16, rounded.pixels.data()};
  } else {
    image = {display.width, display.height, 3, 16, display.pixels.data()};
  }
  image.file_bits = format.file_bits;
  image.quality = format.quality;
  const std::string temp = temp_path_for(path);
  try {
    write_image_file(path, temp, image);
  } catch (const std::exception& e) {
    discard_temp_file(temp);
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  commit_temp_file(temp, path);
}

FrameFilePixels read_frame_file(const std::string& path, const FrameFormat& format) {
  if (!format.exact) throw std::runtime_error(path + ": its pixels are not exact");
  FrameFilePixels pixels;
  if (!format.through_oiio) {
    if (format.linear)
      pixels.linear = read_exr(path);
    else
      pixels.display = read_png16(path);
    return pixels;
  }
  const StoredImage stored = read_stored_image(path);
  const int want_channels = format.linear ? 4 : 3, want_bits = format.linear ? 32 : 16;
  if (stored.channels != want_channels || stored.bits != want_bits)
    throw std::runtime_error(path + " holds " + std::to_string(stored.channels) + " channels of " +
                             std::to_string(stored.bits) + " bits, not the frame's " +
                             std::to_string(want_channels) + " of " + std::to_string(want_bits));
  if (format.linear) {
    ImageRGBA& linear = pixels.linear.emplace(stored.width, stored.height);
    linear.pixels = stored.samples;
  } else {
    ImageRGB16& display = pixels.display.emplace(stored.width, stored.height);
    for (size_t i = 0; i < stored.samples.size(); ++i)
      display.pixels[i] = uint16_t(stored.samples[i]);
  }
  return pixels;
}

}  // namespace sdfreel
