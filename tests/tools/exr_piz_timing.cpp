// Times the frame EXRs' PIZ coding: OpenEXR's own against sdfreel's (io/exr_piz_file.h), on one
// thread (CPU time of the thread) and sdfreel's on all threads (wall time), and checks that every
// frame's bytes are OpenEXR's (docs/startup-and-io.md):
//   cmake --build build --target exr_piz_timing && build/exr_piz_timing out/frames/*.exr
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfOutputFile.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <vector>

#include "io/exr_file.h"
#include "io/exr_memory_stream.h"
#include "io/exr_piz_file.h"

namespace {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

double wall_ms() {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// A frame as encode_exr writes it: RGBA halves, PIZ.
struct Frame {
  Imf::Header header;
  std::vector<Imath::half> halves;
  Imf::FrameBuffer buffer;
};

}  // namespace

int main(int argc, char** argv) {
  using namespace sdfreel;
  if (argc < 2) {
    std::fprintf(stderr, "usage: exr_piz_timing FRAME.exr...\n");
    return 2;
  }
  std::vector<Frame> frames(size_t(argc - 1));
  for (int i = 1; i < argc; ++i) {
    const ImageRGBA img = read_exr_file(argv[i]);
    Frame& f = frames[size_t(i - 1)];
    f.header = Imf::Header(img.width, img.height);
    f.header.compression() = Imf::PIZ_COMPRESSION;
    f.halves.assign(img.pixels.begin(), img.pixels.end());
    const char* names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
      f.header.channels().insert(names[c], Imf::Channel(Imf::HALF));
      f.buffer.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(f.halves.data() + c),
                                           8, 8 * size_t(img.width)));
    }
  }
  constexpr int kRepetitions = 5;
  std::vector<double> theirs, ours, ours_wall;
  size_t differ = 0;
  for (int rep = 0; rep < kRepetitions; ++rep)
    for (const Frame& f : frames) {
      std::vector<char> a, b;
      {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        double start = thread_cpu_ms();
        ExrMemoryStream stream;
        {
          Imf::OutputFile file(stream, f.header, 0);
          file.setFrameBuffer(f.buffer);
          file.writePixels(f.header.dataWindow().max.y + 1);
        }
        a = stream.take();
        theirs.push_back(thread_cpu_ms() - start);
        start = thread_cpu_ms();
        b = encode_piz_exr(f.header, f.buffer);
        ours.push_back(thread_cpu_ms() - start);
      }
      const double start = wall_ms();
      encode_piz_exr(f.header, f.buffer);
      ours_wall.push_back(wall_ms() - start);
      if (rep == 0) differ += a != b;
    }
  std::printf(
      "%zu frames, %d repetitions, medians: OpenEXR %.1f CPU ms/frame, sdfreel's PIZ %.1f on one "
      "thread, %.1f ms wall on all threads; %zu of %zu frames differ from OpenEXR's bytes\n",
      frames.size(), kRepetitions, median(theirs), median(ours), median(ours_wall), differ,
      frames.size());
  return differ ? 1 : 0;
}
