// Two builds testing at once (two clones, the build matrix) must not share scratch folders: the
// temporary folder every test and every sdfreel it starts sees is this build's own.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run.h"

namespace {

TEST(ScratchIsolation, TemporaryFolderIsThisBuildsOwn) {
  const std::string tmp = std::filesystem::temp_directory_path().filename().string();
  EXPECT_EQ(tmp.rfind("sdfreel-tests-", 0), 0u) << tmp;
  // Children (the sdfreel binary under test) inherit it rather than nesting a new one.
  const sdfreel::test::RunResult r = sdfreel::test::run("printf %s \"$TMPDIR\"", ".");
  EXPECT_EQ(r.out, std::filesystem::temp_directory_path().string());
}

}  // namespace
