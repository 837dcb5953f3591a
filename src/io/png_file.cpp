// libpng reports errors by longjmp: the functions that call it keep their C++ objects in the
// caller, and the error handler copies libpng's message out before jumping.
#include "io/png_file.h"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace sdfreel {

namespace {

struct PngErrors {
  char message[256] = "unknown libpng error";
};

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  std::snprintf(errors->message, sizeof errors->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // e.g. "iCCP: known incorrect sRGB profile"

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + size);
}

void no_flush(png_structp) {}

int color_type_of(int channels) {
  switch (channels) {
    case 1:
      return PNG_COLOR_TYPE_GRAY;
    case 2:
      return PNG_COLOR_TYPE_GRAY_ALPHA;
    case 3:
      return PNG_COLOR_TYPE_RGB;
    default:
      return PNG_COLOR_TYPE_RGB_ALPHA;  // 4: encode_png checked the range
  }
}

// Returns false (message in `errors`) on a libpng error.
bool write_png_rows(png_structp png, png_infop info, int width, int height, int channels,
                    int bit_depth, const PngCompression& how, png_bytep* rows,
                    std::vector<unsigned char>* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append_bytes, no_flush);
  png_set_compression_level(png, how.zlib_level);
  png_set_compression_strategy(png, how.strategy);
  if (how.filter >= 0) png_set_filter(png, PNG_FILTER_TYPE_BASE, how.filter);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), bit_depth,
               color_type_of(channels), PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
               PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  if (bit_depth == 16) png_set_swap(png);  // PNG stores 16-bit samples big-endian
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

// Reads the rows of an open file as 16-bit samples of `channels` channels.
bool read_png_rows(png_structp png, png_infop info, std::FILE* file, int channels,
                   PngPixels* pixels, std::vector<png_bytep>* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_read_info(png, info);
  const int type = png_get_color_type(png, info);
  png_set_expand(png);     // palette -> RGB, gray < 8 bit -> 8 bit, tRNS -> alpha
  png_set_expand_16(png);  // 8 -> 16 bit by replicating the byte (v * 257)
  png_set_strip_alpha(png);
  if (channels == 3 && !(type & PNG_COLOR_MASK_COLOR)) png_set_gray_to_rgb(png);
  if (channels == 1 && (type & PNG_COLOR_MASK_COLOR))
    png_set_rgb_to_gray_fixed(png, 1, -1, -1);  // only for odd inputs; our gray files are gray
  png_set_swap(png);
  png_read_update_info(png, info);
  if (int(png_get_channels(png, info)) != channels || png_get_bit_depth(png, info) != 16)
    png_error(png, "unexpected channel layout");
  pixels->width = int(png_get_image_width(png, info));
  pixels->height = int(png_get_image_height(png, info));
  pixels->samples.assign(size_t(pixels->width) * pixels->height * channels, 0);
  rows->resize(size_t(pixels->height));
  for (int y = 0; y < pixels->height; ++y)
    (*rows)[y] =
        reinterpret_cast<png_bytep>(pixels->samples.data() + size_t(y) * pixels->width * channels);
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

std::vector<unsigned char> encode_png(int width, int height, int channels, int bit_depth,
                                      const void* samples, const PngCompression& how) {
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4 ||
      (bit_depth != 8 && bit_depth != 16))
    throw std::runtime_error("PNG: bad image size or bit depth");
  const size_t row_bytes = size_t(width) * channels * (bit_depth / 8);
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  for (int y = 0; y < height; ++y)
    rows[y] = const_cast<png_bytep>(static_cast<const unsigned char*>(samples) + y * row_bytes);
  std::vector<unsigned char> out;
  out.reserve(row_bytes * height / 2);
  PngErrors errors;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok =
      info && write_png_rows(png, info, width, height, channels, bit_depth, how, rows.data(), &out);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error(std::string("PNG encoding failed: ") + errors.message);
  return out;
}

PngPixels read_png(const std::string& path, int channels) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  PngPixels pixels;
  std::vector<png_bytep> rows;
  PngErrors errors;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && read_png_rows(png, info, file.get(), channels, &pixels, &rows);
  png_destroy_read_struct(&png, &info, nullptr);
  if (!ok) throw std::runtime_error("cannot read " + path + ": " + errors.message);
  return pixels;
}

}  // namespace sdfreel
