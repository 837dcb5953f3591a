#include "io/distinct_pixels.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace sdfreel {

namespace {

// Slots of the cache of recent RGBs: a power of two, 16 bytes each, so 64 KiB stays in the core's
// own cache. A collision only replaces the older value (its next twin is converted again).
constexpr size_t kSlots = 4096;

struct Slot {
  uint32_t rgb[3];
  uint32_t distinct;  // 1 + its index among the distinct pixels; 0: empty
};

size_t slot_of(const uint32_t (&rgb)[3]) {
  uint64_t h = (uint64_t(rgb[0]) * 0x9e3779b97f4a7c15ull) ^ rgb[1];
  h = (h * 0xc2b2ae3d27d4eb4full) ^ rgb[2];
  h *= 0x165667b19e3779f9ull;
  return size_t(h >> 52) & (kSlots - 1);
}

}  // namespace

void convert_distinct(float* rgba, size_t n, PixelConversion convert) {
  // Per thread, reused: the display transform calls this for every chunk of rows.
  thread_local std::vector<Slot> slots;
  thread_local std::vector<float> distinct;
  thread_local std::vector<uint32_t> twin;
  slots.assign(kSlots, Slot{});
  distinct.clear();
  twin.resize(n);
  for (size_t i = 0; i < n; ++i) {
    uint32_t rgb[3];
    std::memcpy(rgb, rgba + 4 * i, sizeof rgb);
    Slot& s = slots[slot_of(rgb)];
    if (s.distinct != 0 && std::memcmp(s.rgb, rgb, sizeof rgb) == 0) {
      twin[i] = s.distinct - 1;
      continue;
    }
    twin[i] = uint32_t(distinct.size() / 4);
    distinct.insert(distinct.end(), rgba + 4 * i, rgba + 4 * i + 4);
    std::memcpy(s.rgb, rgb, sizeof rgb);
    s.distinct = twin[i] + 1;
  }
  convert(distinct.data(), distinct.size() / 4);
  for (size_t i = 0; i < n; ++i)
    std::memcpy(rgba + 4 * i, distinct.data() + 4 * size_t(twin[i]), 3 * sizeof(float));
}

}  // namespace sdfreel
