// Hashes: framemd5-compatible MD5, half-float linear hash, SHA-256.
#include "io/hashing.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/frame_files.h"

namespace fs = std::filesystem;

namespace sdfreel {
namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "sdfreel-hash-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path = tmpl;
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

bool have_ffmpeg() {
  return std::system("ffmpeg -version > /dev/null 2>&1") == 0;
}

std::string run_capture(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof(buf), pipe)) > 0) out.append(buf, n);
  pclose(pipe);
  return out;
}

// The hash field of framemd5's data lines ("0, dts, pts, duration, size, hash"), in order.
std::vector<std::string> framemd5_hashes(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    out.push_back(line.substr(line.rfind(' ') + 1));
  }
  return out;
}

ImageRGB16 pattern(int w, int h, uint32_t seed) {
  ImageRGB16 img(w, h);
  for (auto& v : img.pixels) {
    seed = seed * 1664525u + 1013904223u;
    v = uint16_t(seed >> 16);
  }
  return img;
}

TEST(Md5Rgb48le, HashesLittleEndianPackedBytes) {
  // One pixel whose little-endian bytes spell "abcdef" (RFC 1321 style known answer).
  ImageRGB16 img(1, 1);
  img.pixels = {0x6261, 0x6463, 0x6665};
  EXPECT_EQ(md5_rgb48le(img), "e80b5017098950fc58aad83c8c14978e");
}

TEST(Md5Rgb48le, MatchesFfmpegFramemd5OfThePng) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg CLI not found";
  TempDir dir;
  // Larger than the hasher's internal buffer, so its chunking is exercised too.
  const ImageRGB16 img = pattern(211, 97, 99);
  write_png16_atomic(dir.file("x.png"), img);
  const auto hashes =
      framemd5_hashes(run_capture("ffmpeg -v error -i '" + dir.file("x.png") +
                                  "' -pix_fmt rgb48le -fflags +bitexact -f framemd5 -"));
  ASSERT_EQ(hashes.size(), 1u);
  EXPECT_EQ(hashes[0], md5_rgb48le(img));
  EXPECT_NE(md5_rgb48le(pattern(211, 97, 100)), md5_rgb48le(img));
}

TEST(LinearHalfHash, SurvivesTheExrRoundTrip) {
  TempDir dir;
  ImageRGBA img(29, 13);
  uint32_t state = 5;
  for (auto& v : img.pixels) {
    state = state * 1664525u + 1013904223u;
    // Spans tiny (subnormal half), ordinary and large values of both signs.
    v = std::ldexp(float(int32_t(state) >> 8), int(state % 24) - 44);
  }
  write_exr_atomic(dir.file("f.exr"), img, {});
  const ImageRGBA back = read_exr(dir.file("f.exr"));
  EXPECT_NE(back.pixels, img.pixels);  // half precision changed the floats ...
  EXPECT_EQ(linear_half_hash(back), linear_half_hash(img));  // ... but not their half hash
}

TEST(LinearHalfHash, SeesHalfPrecisionChangesOnly) {
  ImageRGBA a(2, 2);
  for (auto& v : a.pixels) v = 1.0f;
  ImageRGBA below_half_ulp = a;
  below_half_ulp.pixels[5] = 1.0f + 1e-4f;  // half's step at 1.0 is 2^-10
  ImageRGBA one_half_ulp = a;
  one_half_ulp.pixels[5] = 1.0f + std::ldexp(1.0f, -10);
  EXPECT_EQ(linear_half_hash(below_half_ulp), linear_half_hash(a));
  EXPECT_NE(linear_half_hash(one_half_ulp), linear_half_hash(a));
  EXPECT_EQ(linear_half_hash(a).size(), 32u);
}

}  // namespace
}  // namespace sdfreel
