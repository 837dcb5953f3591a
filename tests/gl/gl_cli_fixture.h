#pragma once
// End-to-end GL tests through the sdfreel binary: a scratch folder named after the test (kept for
// inspection when the test failed), or a skip where this run's GL platform cannot start.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "gl/gl_fixture.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel::test {

class GlCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    SDFREEL_SKIP_WITHOUT_GL();  // the binary opens the same library
    dir = scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override {
    if (!dir.empty() && !HasFailure()) std::filesystem::remove_all(dir);
  }
  std::string dir;
};

// The frame lines of a framemd5 file, its # header left out ({} when the file is missing).
inline std::vector<std::string> framemd5_frame_lines(const std::string& path) {
  std::istringstream in(read_file(path));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

}  // namespace sdfreel::test
