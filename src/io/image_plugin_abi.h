#pragma once
// The C interface between sdfreel and its image-reading module (src/plugins/image_oiio), which
// links OpenImageIO. A plain C struct and a function pair, so that the module can be opened with
// dlopen only when a timeline reads an image (OIIO loads ~250 shared libraries at start-up).
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
}

// Names of the module and its entry points.
#define SDFREEL_IMAGE_MODULE "sdfreel_image_oiio.so"
#define SDFREEL_IMAGE_READ "sdfreel_image_read_v1"
#define SDFREEL_IMAGE_FREE "sdfreel_image_free_v1"
