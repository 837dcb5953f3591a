#pragma once
// Frame files by extension (docs/timeline.md#frame-formats): what each holds, scene-linear floats
// or display values and in how many bits, and so whether reading it back gives the hashed pixels
// exactly. EXR and PNG are written by OpenEXR and libpng (frame_files.h); every other extension by
// OpenImageIO through the image module (image_plugin.h), loaded only when one is used.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/exr_file.h"
#include "render/compositing_passes.h"
#include "render/image.h"
#include "timeline/frame_file_options.h"

namespace sdfreel {

struct Timeline;

struct FrameFormat {
  std::string ext;      // the file's extension, without the dot
  bool linear = false;  // scene-linear RGBA floats (EXR, 32-bit TIFF); else display RGB
  int file_bits = 16;   // bits a sample in the file (EXR: 16, half)
  int quality = 0;      // 1-100 for JPEG; 0 otherwise
  // Reading it back gives the manifest's pixels bit for bit: the half RGBA of the linear hash
  // (EXR; 32-bit TIFF, whose floats round to the same halves) or the 16-bit display values (PNG,
  // 16-bit TIFF and DPX). Fewer bits, and JPEG, only deliver: a frame is checked by an exact file
  // beside them, or cannot be.
  bool exact = false;
  bool through_oiio = true;
  ExrSettings exr;  // for "exr"
};

FrameFormat frame_format(const std::string& ext, const FrameFileOptions& options);
// The extensions of the frame files a timeline asks for: exr and png first, as before.
std::vector<std::string> timeline_frame_files(const Timeline& tl);

// The options that shape the files of these extensions, by their [output] key ("tiff_bits":
// "16"), for the manifest: every option of a format beyond EXR and PNG, EXR's when not the
// default (PIZ, half), and its compositing passes ("passes": "samples,sdf_evals"); empty for the
// default EXR and PNG.
std::map<std::string, std::string> frame_option_values(const std::vector<std::string>& exts,
                                                       const FrameFileOptions& options);
// Reads back what shapes how a kept file reads (keys it does not know, and "passes", which only
// add channels a reader skips, are ignored; missing ones keep their defaults).
FrameFileOptions frame_options_from_values(const std::map<std::string, std::string>& values);

// Writes one frame file atomically (temporary beside it, then rename), from the linear or the
// display pixels as its format takes; an EXR carries `passes` as channels of their own. Throws
// std::runtime_error naming `path`.
void write_frame_file(const std::string& path, const FrameFormat& format, const ImageRGBA& linear,
                      const ImageRGB16& display, const std::map<std::string, std::string>& metadata,
                      const std::vector<PassImage>& passes = {});

// What an exact format's file gives back: the linear pixels (EXR, 32-bit TIFF) or the display
// ones. Throws std::runtime_error for an unreadable file or one of other contents.
struct FrameFilePixels {
  std::optional<ImageRGBA> linear;
  std::optional<ImageRGB16> display;
};
FrameFilePixels read_frame_file(const std::string& path, const FrameFormat& format);

}  // namespace sdfreel
