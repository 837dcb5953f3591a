#pragma once
// The C interface between sdfreel and its image module (src/plugins/image_oiio), which links
// OpenImageIO. Plain C structs and functions, so that the module can be opened with dlopen only
// when a timeline reads an image or writes a frame format beyond EXR and PNG (OIIO loads ~250
// shared libraries at start-up).
#include <stddef.h>

extern "C" {

// An image as stored: `channels` interleaved samples per pixel, row 0 at the top. `bits` is 8 or
// 16 for unsigned integer files (samples are uint8_t / uint16_t) and 32 for everything else
// (samples are float: half, float, HDR's RGBE, signed or 32-bit integers converted by OIIO).
struct SdfreelStoredImage {
  int width, height, channels, bits;
  void* samples;  // malloc'ed by the module; give it back with sdfreel_image_free
};

// Reads the first subimage's top mip level, at most 4 channels. Returns 1, or 0 with a message.
typedef int (*SdfreelImageReadFn)(const char* path, SdfreelStoredImage* out, char* error,
                                  size_t error_size);
typedef void (*SdfreelImageFreeFn)(SdfreelStoredImage* image);

// An image to write: `channels` interleaved samples per pixel, row 0 at the top, uint16_t when
// `sample_bits` is 16 and float when it is 32. The file's format is chosen by `format_name`'s
// extension and the bytes go to `path` (a temporary the caller renames).
struct SdfreelImageToWrite {
  const char* format_name;
  const char* path;
  int width, height, channels, sample_bits;
  const void* samples;
  int file_bits;         // bits a sample in the file: 8, 10, 12, 16 or 32 (float); 0: as given
  int quality;           // 1-100 for lossy formats (JPEG, WebP); 0: the format's default
  const char* software;  // written into the file's Software tag
};

// Returns 1, or 0 with a message.
typedef int (*SdfreelImageWriteFn)(const SdfreelImageToWrite* image, char* error,
                                   size_t error_size);
// 1 when OpenImageIO has a writer for files with this extension (without the dot).
typedef int (*SdfreelImageWritesFn)(const char* extension);
}

// Names of the module and its entry points.
#define SDFREEL_IMAGE_MODULE "sdfreel_image_oiio.so"
#define SDFREEL_IMAGE_READ "sdfreel_image_read_v1"
#define SDFREEL_IMAGE_FREE "sdfreel_image_free_v1"
#define SDFREEL_IMAGE_WRITE "sdfreel_image_write_v1"
#define SDFREEL_IMAGE_WRITES "sdfreel_image_writes_v1"
