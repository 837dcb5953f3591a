#pragma once
// Shared set-up of the GL tests: a context on the platform SDFREEL_GL_PLATFORM names (ctest runs
// the suite once per platform; unset: EGL, else OSMesa), or a skip that says why there is none, and
// a scratch shader folder holding the test shaders beside links to the real shader folders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>

#include "backends/gl/gl_driver.h"
#include "backends/gl/gl_platform_choice.h"

namespace sdfreel::test {

// A scratch folder: tests/gl/shaders/* copied in, links to <source>/shaders/<folder>. Removed
// when the test program exits.
inline std::string test_shader_dir() {
  namespace fs = std::filesystem;
  struct ScratchDir {
    fs::path path;
    ScratchDir() {
      path = fs::temp_directory_path() / ("sdfreel-gl-shaders-" + std::to_string(::getpid()));
      fs::remove_all(path);
      fs::create_directories(path);
      const fs::path src = fs::path(SDFREEL_SOURCE_DIR);
      for (const auto& e : fs::directory_iterator(src / "shaders"))  // common/, scene folders
        if (e.is_directory()) fs::create_directory_symlink(e.path(), path / e.path().filename());
      for (const auto& e : fs::directory_iterator(src / "tests" / "gl" / "shaders"))
        fs::copy_file(e.path(), path / e.path().filename());
    }
    ~ScratchDir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const ScratchDir dir;
  return dir.path.string();
}

// The platform of this run (or the one named), or nullptr with the reason in *why.
inline std::unique_ptr<GlPlatform> try_gl_platform(std::string* why,
                                                   const std::string& platform = "") {
  try {
    return make_gl_platform({platform, ""});
  } catch (const GlPlatformError& e) {
    *why = e.what();
    return nullptr;
  }
}

// Skips the test (from SetUp) when this run's platform cannot start: the binary would fail too.
#define SDFREEL_SKIP_WITHOUT_GL()                          \
  do {                                                     \
    std::string why_;                                      \
    if (!::sdfreel::test::try_gl_platform(&why_))          \
      GTEST_SKIP() << "GL platform unavailable: " << why_; \
  } while (0)

// Each test gets a fresh context and driver; without the platform the test is skipped with the
// reason.
class GlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    platform = try_gl_platform(&why);
    if (!platform) GTEST_SKIP() << "GL platform unavailable: " << why;
    driver = std::make_unique<GlDriver>(*platform, test_shader_dir());
  }
  void TearDown() override {
    if (!platform) return;
    platform->make_current();
    driver.reset();
  }
  std::unique_ptr<GlPlatform> platform;
  std::unique_ptr<GlDriver> driver;
};

}  // namespace sdfreel::test
