#include "cli/output_checks.h"

#include <stdexcept>

#include "io/image_plugin.h"
#include "io/video_codecs.h"

namespace sdfreel {

std::string unwritable_frame_format(const std::string& ext) {
  try {
    if (image_module_writes(ext)) return "";
  } catch (const std::exception& e) {
    return "." + ext + " files need OpenImageIO: " + e.what();
  }
  return "OpenImageIO on this machine writes no ." + ext + " files";
}

void validate_frame_formats(const Timeline& tl) {
  for (const Timeline::OtherFrames& f : tl.other_frames)
    if (std::string problem = unwritable_frame_format(f.ext); !problem.empty())
      throw InputError(tl.path, f.line, f.column,
                       "output.frames: " + problem +
                           "; use exr, png, tiff, tif, dpx, jpg or the extension of another "
                           "format it writes");
}

void validate_video_encoder(const Timeline& tl, bool makes_video) {
  if (!makes_video || tl.video.empty()) return;
  if (std::string missing = missing_video_encoder(tl.codec); !missing.empty())
    throw InputError(tl.path, 0, 0, "output.codec: " + missing);
}

}  // namespace sdfreel
