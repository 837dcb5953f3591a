// libFuzzer target: the timeline parser and validator on arbitrary bytes. Bad input must end in
// InputError (exit 2 in sdfreel); any other exception, crash, hang or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenes/registry.h"
#include "timeline/timeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    sdfreel::Timeline tl =
        sdfreel::parse_timeline(sdfreel::all_scenes(), "fuzz.toml", text, nullptr);
    // What render does with a valid timeline before the first frame: frame count, times, camera.
    sdfreel::validate_overrides(tl, true);
    const int frames = tl.frame_count();
    for (int i : {0, frames / 2, frames - 1}) {
      (void)tl.scene_time(i);
      (void)tl.camera.sample(tl.video_time(i), sdfreel::CameraPose{});
    }
  } catch (const sdfreel::InputError&) {
  }
  return 0;
}
