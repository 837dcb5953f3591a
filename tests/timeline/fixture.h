#pragma once
// Test support: timeline files written into a fresh temporary folder per test, and a check that
// loading one fails with a given message at a given line and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scenes/registry.h"
#include "timeline/timeline.h"

namespace sdfreel::testing {

class TimelineFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("sdfreel_timeline_" + std::string(info->test_suite_name()) + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes `text` as dir/name and returns its path.
  std::string write(const std::string& text, const std::string& name = "test.toml") {
    const std::filesystem::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  // Loads `text` and expects an InputError whose message contains `message`, at line:column.
  void expect_error(const std::string& text, const std::string& message, int line, int column,
                    const ColorChecker* color = nullptr) {
    const std::string path = write(text);
    try {
      load_timeline(all_scenes(), path, color);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos)
          << "message: " << e.what() << "\nwanted: " << message;
      EXPECT_EQ(e.file, path);
      EXPECT_EQ(e.line, line) << e.formatted();
      EXPECT_EQ(e.column, column) << e.formatted();
      if (line > 0 && column > 0) {
        const std::string prefix =
            path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: ";
        EXPECT_EQ(e.formatted(), prefix + e.what());
      }
    }
  }

  std::filesystem::path dir_;
};

// The first two lines of most fixtures; the line under test is line 3.
inline std::string video_with(const std::string& line3) {
  return "[video]\nscene = \"sdf_morph\"\n" + line3 + "\n";
}

}  // namespace sdfreel::testing
