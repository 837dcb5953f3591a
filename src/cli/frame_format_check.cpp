#include "cli/frame_format_check.h"

#include <stdexcept>

#include "io/image_plugin.h"

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

}  // namespace sdfreel
