#include "io/palette.h"

#include <algorithm>

namespace sdfreel {
namespace {

// Colours are binned at 5 bits a channel (32768 bins): the cut works on bins, each with its
// population and the sum of its pixels' 8-bit values, so a box's colour is its pixels' mean.
constexpr int kBits = 5, kBins = 1 << (3 * kBits);

struct Bin {
  uint32_t count = 0;
  uint64_t sum[3] = {0, 0, 0};
};

int bin_of(const uint8_t rgb[3]) {
  return (rgb[0] >> (8 - kBits)) << (2 * kBits) | (rgb[1] >> (8 - kBits)) << kBits |
         (rgb[2] >> (8 - kBits));
}

int channel(int bin, int c) {
  return (bin >> (kBits * (2 - c))) & ((1 << kBits) - 1);
}

struct Box {
  std::vector<int> bins;  // non-empty bins, in index order
  uint64_t population = 0;
  int longest = 0, range = 0;  // the channel with the widest spread, and that spread
};

Box make_box(std::vector<int> bins, const std::vector<Bin>& hist) {
  Box b;
  b.bins = std::move(bins);
  int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
  for (int i : b.bins) {
    b.population += hist[size_t(i)].count;
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], channel(i, c));
      hi[c] = std::max(hi[c], channel(i, c));
    }
  }
  for (int c = 0; c < 3; ++c)
    if (hi[c] - lo[c] > b.range) {
      b.range = hi[c] - lo[c];
      b.longest = c;
    }
  return b;
}

uint8_t to_8bit(uint16_t v) {
  return uint8_t((uint32_t(v) * 255 + 32767) / 65535);
}

}  // namespace

PalettedImage median_cut_palette(const ImageRGB16& display) {
  const size_t pixels = size_t(display.width) * display.height;
  std::vector<uint8_t> rgb(pixels * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = to_8bit(display.pixels[i]);
  std::vector<Bin> hist(kBins);
  for (size_t p = 0; p < pixels; ++p) {
    const int b = bin_of(&rgb[p * 3]);
    hist[size_t(b)].count++;
    for (int c = 0; c < 3; ++c) hist[size_t(b)].sum[c] += rgb[p * 3 + c];
  }
  std::vector<int> used;
  for (int i = 0; i < kBins; ++i)
    if (hist[size_t(i)].count) used.push_back(i);

  std::vector<Box> boxes = {make_box(used, hist)};
  while (boxes.size() < 256) {
    // The most populous box that can still be split (first of equals: a stable choice).
    int pick = -1;
    for (size_t k = 0; k < boxes.size(); ++k)
      if (boxes[k].bins.size() > 1 &&
          (pick < 0 || boxes[k].population > boxes[size_t(pick)].population))
        pick = int(k);
    if (pick < 0) break;
    Box& box = boxes[size_t(pick)];
    const int c = box.longest;
    std::stable_sort(box.bins.begin(), box.bins.end(),
                     [c](int a, int b) { return channel(a, c) < channel(b, c); });
    // Split where half the population lies on each side, leaving at least one bin in each.
    uint64_t seen = 0;
    size_t cut = 1;
    for (; cut < box.bins.size(); ++cut) {
      seen += hist[size_t(box.bins[cut - 1])].count;
      if (2 * seen >= box.population) break;
    }
    cut = std::min(cut, box.bins.size() - 1);
    std::vector<int> low(box.bins.begin(), box.bins.begin() + std::ptrdiff_t(cut));
    std::vector<int> high(box.bins.begin() + std::ptrdiff_t(cut), box.bins.end());
    box = make_box(std::move(low), hist);
    boxes.push_back(make_box(std::move(high), hist));
  }

  PalettedImage out;
  out.palette.fill(0xff000000u);
  std::vector<int> colour(size_t(boxes.size()) * 3);
  for (size_t k = 0; k < boxes.size(); ++k) {
    uint64_t sum[3] = {0, 0, 0};
    for (int i : boxes[k].bins)
      for (int c = 0; c < 3; ++c) sum[c] += hist[size_t(i)].sum[c];
    const uint64_t n = std::max<uint64_t>(boxes[k].population, 1);
    for (int c = 0; c < 3; ++c) colour[k * 3 + size_t(c)] = int((sum[c] + n / 2) / n);
    out.palette[k] = 0xff000000u | uint32_t(colour[k * 3]) << 16 |
                     uint32_t(colour[k * 3 + 1]) << 8 | uint32_t(colour[k * 3 + 2]);
  }
  // Each pixel's nearest entry by its own 8-bit colour (not its bin's): 256 distances a pixel,
  // a tenth of a second for a 640x360 frame, fine for the short loops GIF is for.
  out.indices.resize(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    int best = 0;
    long best_d = -1;
    for (size_t k = 0; k < boxes.size(); ++k) {
      long d = 0;
      for (int c = 0; c < 3; ++c) {
        const long e = long(rgb[p * 3 + size_t(c)]) - colour[k * 3 + size_t(c)];
        d += e * e;
      }
      if (best_d < 0 || d < best_d) {
        best_d = d;
        best = int(k);
      }
    }
    out.indices[p] = uint8_t(best);
  }
  return out;
}

}  // namespace sdfreel
