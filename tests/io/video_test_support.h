#pragma once
// Synthetic frames, a scratch folder and a one-call encode for the video tests.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/video_encoder.h"
#include "render/image.h"
#include "support/solid_image.h"

namespace sdfreel::test {

// Gradients over the whole 16-bit range that differ in every frame and channel.
inline ImageRGB16 gradient_frame(int w, int h, int index) {
  ImageRGB16 img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint16_t* p = &img.pixels[(size_t(y) * w + x) * 3];
      p[0] = uint16_t((x * 65535) / (w - 1) + index * 997);
      p[1] = uint16_t((y * 65535) / (h - 1) + index * 4099);
      p[2] = uint16_t(x * 1021 + y * 7919 + index * 31337);
    }
  return img;
}

inline void encode_video(const std::string& path, const std::string& codec,
                         const std::vector<ImageRGB16>& frames, Rational fps = {30, 1}) {
  VideoSettings s;
  s.path = path;
  s.codec = codec;
  s.width = frames.at(0).width;
  s.height = frames.at(0).height;
  s.fps = fps;
  VideoEncoder enc(s);
  for (const ImageRGB16& f : frames) enc.add_frame(f);
  enc.finish();
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

inline std::vector<std::string> list_dir(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  return names;
}

// A fresh, empty folder per test, removed afterwards.
class VideoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("sdfreel_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace sdfreel::test
