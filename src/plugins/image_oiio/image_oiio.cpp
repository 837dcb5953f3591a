// sdfreel's image module: reads any format OpenImageIO reads (PNG, JPEG, EXR, HDR, TIFF, ...),
// returned as stored (8/16-bit integers or floats), and writes frame files in the formats beyond
// EXR and PNG (TIFF, DPX, JPEG, ...). Opened with dlopen on first use (src/io/image_plugin.cpp);
// it holds no state.
#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "io/image_plugin_abi.h"

namespace {

int fail(const std::string& message, char* error, size_t size) {
  if (size) {
    std::strncpy(error, message.c_str(), size - 1);
    error[size - 1] = '\0';
  }
  return 0;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int sdfreel_image_read_v1(const char* path,
                                                                            SdfreelStoredImage* out,
                                                                            char* error,
                                                                            size_t error_size) {
  try {
    // The samples as stored: OIIO would otherwise multiply colour by alpha in PNG and others
    // (WebGL, and so Shadertoy, uploads them unpremultiplied).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) return fail(OIIO::geterror(), error, error_size);
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
      return fail("not a 2D image", error, error_size);
    const OIIO::TypeDesc stored = spec.format;
    const OIIO::TypeDesc type = stored == OIIO::TypeDesc::UINT8    ? OIIO::TypeDesc::UINT8
                                : stored == OIIO::TypeDesc::UINT16 ? OIIO::TypeDesc::UINT16
                                                                   : OIIO::TypeDesc::FLOAT;
    const int channels = spec.nchannels < 4 ? spec.nchannels : 4;
    const size_t bytes = size_t(spec.width) * size_t(spec.height) * size_t(channels) * type.size();
    void* samples = std::malloc(bytes);
    if (!samples) return fail("out of memory", error, error_size);
    if (!in->read_image(0, 0, 0, channels, type, samples)) {
      std::free(samples);
      return fail(in->geterror(), error, error_size);
    }
    *out = {spec.width, spec.height, channels, int(type.size() * 8), samples};
    return 1;
  } catch (const std::exception& e) {
    return fail(e.what(), error, error_size);
  }
}

extern "C" __attribute__((visibility("default"))) void sdfreel_image_free_v1(
    SdfreelStoredImage* image) {
  std::free(image->samples);
  image->samples = nullptr;
}

namespace {

OIIO::TypeDesc file_type(int file_bits, int sample_bits) {
  const int bits = file_bits ? file_bits : sample_bits;
  if (bits == 8) return OIIO::TypeDesc::UINT8;
  if (bits <= 16) return OIIO::TypeDesc::UINT16;
  return OIIO::TypeDesc::FLOAT;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int sdfreel_image_write_v1(
    const SdfreelImageToWrite* image, char* error, size_t error_size) {
  try {
    auto out = OIIO::ImageOutput::create(image->format_name);
    if (!out) return fail(OIIO::geterror(), error, error_size);
    OIIO::ImageSpec spec(image->width, image->height, image->channels,
                         file_type(image->file_bits, image->sample_bits));
    if (image->file_bits == 10 || image->file_bits == 12)
      spec.attribute("oiio:BitsPerSample", image->file_bits);
    if (image->channels == 4) spec.alpha_channel = 3;
    if (image->quality > 0)
      spec.attribute("Compression",
                     std::string(out->format_name()) + ":" + std::to_string(image->quality));
    else if (std::strcmp(out->format_name(), "tiff") == 0)
      spec.attribute("Compression", "zip");
    if (image->software) spec.attribute("Software", image->software);
    // The samples are display values or scene-linear floats, never premultiplied by an alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(image->path, spec)) return fail(out->geterror(), error, error_size);
    const OIIO::TypeDesc given =
        image->sample_bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::FLOAT;
    const bool wrote = out->write_image(given, image->samples);
    const bool closed = out->close();
    if (!wrote || !closed) return fail(out->geterror(), error, error_size);
    return 1;
  } catch (const std::exception& e) {
    return fail(e.what(), error, error_size);
  }
}

extern "C" __attribute__((visibility("default"))) int sdfreel_image_writes_v1(
    const char* extension) {
  try {
    return OIIO::ImageOutput::create(std::string("frame.") + extension) ? 1 : 0;
  } catch (const std::exception&) {
    return 0;
  }
}
