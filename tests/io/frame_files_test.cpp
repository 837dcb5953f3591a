// EXR / PNG frame files: round trips, metadata, atomic publication, FFmpeg compatibility.
#include "io/frame_files.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/exr_file.h"

namespace fs = std::filesystem;

namespace sdfreel {
namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "sdfreel-frames-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path = tmpl;
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::set<std::string> names() const {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(path)) out.insert(e.path().filename().string());
    return out;
  }
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

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every 16-bit value pattern shows up: deterministic, but with no structure a codec could hide.
ImageRGB16 noisy_display(int w, int h) {
  ImageRGB16 img(w, h);
  uint32_t state = 12345;
  for (auto& v : img.pixels) {
    state = state * 1664525u + 1013904223u;
    v = uint16_t(state >> 16);
  }
  img.pixels[0] = 0;
  img.pixels[1] = 65535;
  return img;
}

ImageRGBA noisy_linear(int w, int h) {
  ImageRGBA img(w, h);
  uint32_t state = 777;
  for (auto& v : img.pixels) {
    state = state * 1664525u + 1013904223u;
    v = std::ldexp(float(state >> 8), -20) - 2.0f;  // [-2, 14), most values not halves
  }
  return img;
}

TEST(Png16, RoundTripsExactly) {
  TempDir dir;
  const ImageRGB16 img = noisy_display(37, 23);
  write_png16_atomic(dir.file("00012.png"), img);
  const ImageRGB16 back = read_png16(dir.file("00012.png"));
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.pixels, img.pixels);
  EXPECT_EQ(dir.names(), std::set<std::string>{"00012.png"});
}

TEST(Png16, FfmpegReadsTheSameRgb48) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg CLI not found";
  TempDir dir;
  const ImageRGB16 img = noisy_display(40, 18);
  write_png16_atomic(dir.file("f.png"), img);
  const std::string raw =
      run_capture("ffmpeg -v error -i '" + dir.file("f.png") + "' -pix_fmt rgb48le -f rawvideo -");
  std::string expected;
  for (uint16_t v : img.pixels) {
    expected.push_back(char(v & 0xff));
    expected.push_back(char(v >> 8));
  }
  ASSERT_EQ(raw.size(), expected.size());
  EXPECT_TRUE(raw == expected);
}

TEST(Png16, SameImageGivesTheSameFileBytes) {
  TempDir dir;
  const ImageRGB16 img = noisy_display(16, 9);
  write_png16_atomic(dir.file("a.png"), img);
  write_png16_atomic(dir.file("b.png"), img);
  const std::string a = read_bytes(dir.file("a.png"));
  EXPECT_FALSE(a.empty());
  EXPECT_TRUE(a == read_bytes(dir.file("b.png")));
}

TEST(Exr, RoundTripsAsHalvesWithMetadata) {
  TempDir dir;
  const ImageRGBA img = noisy_linear(33, 17);
  const std::map<std::string, std::string> meta = {{"scene", "lantern_festival"}, {"frame", "12"}};
  write_exr_atomic(dir.file("00012.exr"), img, meta);
  EXPECT_EQ(dir.names(), std::set<std::string>{"00012.exr"});

  const ImageRGBA back = read_exr(dir.file("00012.exr"));
  ASSERT_EQ(back.width, 33);
  ASSERT_EQ(back.height, 17);
  ASSERT_EQ(back.pixels.size(), img.pixels.size());
  size_t changed = 0;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    EXPECT_EQ(back.pixels[i], float(Imath::half(img.pixels[i]))) << i;
    changed += back.pixels[i] != img.pixels[i];
  }
  EXPECT_GT(changed, 0u);  // the data really went through half precision

  Imf::InputFile in(dir.file("00012.exr").c_str());
  int channels = 0;
  for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c, ++channels)
    EXPECT_EQ(c.channel().type, Imf::HALF) << c.name();
  EXPECT_EQ(channels, 4);
  EXPECT_EQ(in.header().compression(), Imf::PIZ_COMPRESSION);
  const auto strings = read_exr_strings(dir.file("00012.exr"));
  EXPECT_EQ(strings.at("sdfreel:scene"), "lantern_festival");
  EXPECT_EQ(strings.at("sdfreel:frame"), "12");
}

TEST(Exr, SameImageGivesTheSameFileBytes) {
  TempDir dir;
  const ImageRGBA img = noisy_linear(20, 11);
  write_exr_atomic(dir.file("a.exr"), img, {{"k", "v"}});
  write_exr_atomic(dir.file("b.exr"), img, {{"k", "v"}});
  EXPECT_TRUE(read_bytes(dir.file("a.exr")) == read_bytes(dir.file("b.exr")));
}

TEST(AtomicWrites, ReplaceAnExistingFileAndLeaveNoTemporaries) {
  TempDir dir;
  write_png16_atomic(dir.file("f.png"), noisy_display(8, 8));
  const ImageRGB16 second = noisy_display(5, 3);
  write_png16_atomic(dir.file("f.png"), second);
  EXPECT_EQ(read_png16(dir.file("f.png")).pixels, second.pixels);

  write_text_atomic(dir.file("manifest.json"), "first");
  write_text_atomic(dir.file("manifest.json"), "{\"second\": true}\n");
  EXPECT_EQ(read_bytes(dir.file("manifest.json")), "{\"second\": true}\n");
  write_text_atomic(dir.file("empty.txt"), "");
  EXPECT_TRUE(fs::exists(dir.file("empty.txt")));
  EXPECT_EQ(fs::file_size(dir.file("empty.txt")), 0u);

  EXPECT_EQ(dir.names(), (std::set<std::string>{"f.png", "manifest.json", "empty.txt"}));
}

TEST(AtomicWrites, FailuresThrowAndLeaveNothingBehind) {
  TempDir dir;
  const std::string missing_dir = dir.file("no/such/dir/f.png");
  EXPECT_THROW(write_png16_atomic(missing_dir, noisy_display(4, 4)), std::runtime_error);
  EXPECT_THROW(write_text_atomic(dir.file("no/such/dir/m.json"), "x"), std::runtime_error);

  ImageRGB16 inconsistent(4, 4);
  inconsistent.pixels.pop_back();
  EXPECT_THROW(write_png16_atomic(dir.file("bad.png"), inconsistent), std::runtime_error);
  EXPECT_THROW(write_exr_atomic(dir.file("bad.exr"), ImageRGBA(), {}), std::runtime_error);
  EXPECT_TRUE(dir.names().empty());
}

TEST(Readers, RefuseMissingAndWrongFiles) {
  TempDir dir;
  EXPECT_THROW(read_png16(dir.file("missing.png")), std::runtime_error);
  EXPECT_THROW(read_exr(dir.file("missing.exr")), std::runtime_error);
  write_text_atomic(dir.file("not_an_image.png"), "hello");
  EXPECT_THROW(read_png16(dir.file("not_an_image.png")), std::runtime_error);
}

}  // namespace
}  // namespace sdfreel
