#pragma once
// Shared set-up of the OSMesa tests: a context (or a skip that says why there is none) and a
// scratch shader folder holding the test shaders beside links to the real shader folders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>

#include "backends/osmesa/gl_driver.h"
#include "backends/osmesa/osmesa_platform.h"

namespace sdfreel::test {

// A scratch folder: tests/osmesa/shaders/* copied in, links to <source>/shaders/<folder>. Removed
// when the test program exits.
inline std::string test_shader_dir() {
  namespace fs = std::filesystem;
  struct ScratchDir {
    fs::path path;
    ScratchDir() {
      path = fs::temp_directory_path() / ("sdfreel-osmesa-shaders-" + std::to_string(::getpid()));
      fs::remove_all(path);
      fs::create_directories(path);
      const fs::path src = fs::path(SDFREEL_SOURCE_DIR);
      for (const auto& e : fs::directory_iterator(src / "shaders"))  // common/, scene folders
        if (e.is_directory()) fs::create_directory_symlink(e.path(), path / e.path().filename());
      for (const auto& e : fs::directory_iterator(src / "tests" / "osmesa" / "shaders"))
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

// Each test gets a fresh context and driver; without OSMesa the test is skipped with the reason.
class OsmesaTest : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      platform = std::make_unique<OsmesaPlatform>();
    } catch (const GlPlatformError& e) {
      GTEST_SKIP() << "OSMesa unavailable: " << e.what();
    }
    driver = std::make_unique<GlDriver>(*platform, test_shader_dir());
  }
  void TearDown() override {
    if (!platform) return;
    platform->make_current();
    driver.reset();
  }
  std::unique_ptr<OsmesaPlatform> platform;
  std::unique_ptr<GlDriver> driver;
};

}  // namespace sdfreel::test
