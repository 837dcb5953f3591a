// Measures PNG encoding of rendered frames at each zlib level and row filter, to choose the
// frame files' setting (docs/startup-and-io.md):
//   cmake --build build --target png_levels && build/png_levels out/frames/*.png
// Prints, per setting, the median CPU time to encode a frame and the mean size of a frame; then
// the frame files' own coder's time, and whether its bytes are libpng's for every frame.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "io/png_file.h"
#include "io/png_frames.h"

// CPU time of this thread: on a shared machine, wall time measures the other users too.
double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

int main(int argc, char** argv) {
  using namespace sdfreel;
  std::vector<PngPixels> frames;
  for (int i = 1; i < argc; ++i) frames.push_back(read_png(argv[i], 3));
  if (frames.empty()) {
    std::fprintf(stderr, "usage: png_levels FRAME.png...\n");
    return 2;
  }
  const struct {
    const char* name;
    int mask;
  } filters[] = {{"none", 0x08}, {"up", 0x20}, {"paeth", 0x80}, {"adaptive", 0xf8}};
  const char* strategies[] = {"default", "filtered", "huffman only", "rle"};
  std::vector<PngCompression> settings;
  for (int level : {0, 1, 2, 3, 6})
    for (const auto& f : filters) settings.push_back({level, f.mask, 0});
  for (int strategy : {2, 3})
    for (const auto& f : filters) settings.push_back({1, f.mask, strategy});
  // Repetitions interleave the settings, so that load from elsewhere spreads over all of them.
  constexpr int kRepetitions = 3;
  std::vector<std::vector<double>> ms(settings.size());
  std::vector<size_t> bytes(settings.size(), 0);
  for (int rep = 0; rep < kRepetitions; ++rep)
    for (const PngPixels& p : frames)
      for (size_t s = 0; s < settings.size(); ++s) {
        const double start = thread_cpu_ms();
        const size_t n = encode_png(p.width, p.height, 3, 16, p.samples.data(), settings[s]).size();
        ms[s].push_back(thread_cpu_ms() - start);
        if (rep == 0) bytes[s] += n;
      }
  std::printf("%zu frames of %dx%d, %d repetitions\n\n", frames.size(), frames[0].width,
              frames[0].height, kRepetitions);
  std::printf(
      "| zlib level | strategy | filter | CPU ms/frame (median) | MB/frame |\n"
      "| ---: | --- | --- | ---: | ---: |\n");
  for (size_t s = 0; s < settings.size(); ++s) {
    std::nth_element(ms[s].begin(), ms[s].begin() + ms[s].size() / 2, ms[s].end());
    const char* filter = "";
    for (const auto& f : filters)
      if (f.mask == settings[s].filter) filter = f.name;
    std::printf("| %d | %s | %s | %.1f | %.3f |\n", settings[s].zlib_level,
                strategies[settings[s].strategy], filter, ms[s][ms[s].size() / 2],
                double(bytes[s]) / 1e6 / double(frames.size()));
  }
  // The frame files' own coder (io/png_frames.h): its time, and its bytes against libpng's.
  std::vector<double> own;
  size_t differ = 0;
  for (int rep = 0; rep < kRepetitions; ++rep)
    for (const PngPixels& p : frames) {
      const double start = thread_cpu_ms();
      const std::vector<unsigned char> b =
          encode_png_paeth_huffman(p.width, p.height, 3, 16, p.samples.data());
      own.push_back(thread_cpu_ms() - start);
      if (rep == 0)
        differ += b != encode_png(p.width, p.height, 3, 16, p.samples.data(), PAETH_HUFFMAN_ONLY);
    }
  std::nth_element(own.begin(), own.begin() + own.size() / 2, own.end());
  std::printf(
      "\nframes' own coder (Paeth, Huffman only): %.1f CPU ms/frame (median), %zu of %zu "
      "frames not libpng's bytes\n",
      own[own.size() / 2], differ, frames.size());
  return differ == 0 ? 0 : 1;
}
