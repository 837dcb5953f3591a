// libFuzzer target: the --frames, --shard and --resolution parsers. The first byte picks the
// parser and the frame count; bad input must end in UsageError (exit 2), and what is accepted
// must be in range: sorted unique frames below the count, a shard inside the frame list.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "pipeline/errors.h"
#include "cli/frame_range.h"
#include "cli/option_numbers.h"
#include "timeline/rules.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const int which = data[0] % 3;
  const int count = 1 + (data[0] >> 2) * 97;  // up to ~6000 frames: keeps each run fast
  const std::string spec(reinterpret_cast<const char*>(data + 1), size - 1);
  std::vector<int> all(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) all[size_t(i)] = i;
  try {
    if (which == 0) {
      const std::vector<int> frames = sdfreel::parse_frame_list(spec, count);
      if (frames.empty() || !std::is_sorted(frames.begin(), frames.end()) ||
          std::adjacent_find(frames.begin(), frames.end()) != frames.end() || frames.front() < 0 ||
          frames.back() >= count)
        std::abort();
    } else if (which == 1) {
      const std::vector<int> part = sdfreel::shard_of(all, spec);
      if (part.size() > all.size() || (!part.empty() && (part.front() < 0 || part.back() >= count)))
        std::abort();
    } else {
      const sdfreel::Resolution r = sdfreel::parse_resolution_option(spec);
      if (r.width < 0 || r.height < 0) std::abort();
    }
  } catch (const sdfreel::UsageError&) {
  }
  return 0;
}
