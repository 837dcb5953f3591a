#pragma once
// [output] settings of the frame files OpenImageIO writes (docs/timeline.md): plain numbers, so
// that the timeline, the manifest and the writer share them.
namespace sdfreel {

struct FrameFileOptions {
  int tiff_bits = 16;     // 8 or 16 (display values) or 32 (scene-linear floats)
  int dpx_bits = 10;      // 8, 10, 12 or 16 (display values)
  int jpeg_quality = 95;  // 1-100
};

}  // namespace sdfreel
