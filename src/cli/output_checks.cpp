#include "cli/output_checks.h"

#include <stdexcept>

#include "io/image_plugin.h"
#include "io/video_codecs.h"

namespace sdfreel {

void validate_frame_formats(const Timeline& tl) {
  for (const Timeline::OtherFrames& f : tl.other_frames) {
    bool writes = false;
    try {
      writes = image_module_writes(f.ext);
    } catch (const std::exception& e) {
      throw InputError(tl.path, f.line, f.column,
                       "output.frames: \"" + f.ext + "\" needs OpenImageIO: " + e.what());
    }
    if (!writes)
      throw InputError(tl.path, f.line, f.column,
                       "output.frames: OpenImageIO on this machine writes no ." + f.ext +
                           " files; use exr, png, tiff, tif, dpx, jpg or the extension of "
                           "another format it writes");
  }
}

void validate_video_encoder(const Timeline& tl, bool makes_video) {
  if (!makes_video || tl.video.empty()) return;
  if (std::string missing = missing_video_encoder(tl.codec); !missing.empty())
    throw InputError(tl.path, 0, 0, "output.codec: " + missing);
}

}  // namespace sdfreel
