// Golden hashes: small renders must reproduce the committed frames.framemd5 bit for bit.
// After an intended change of the picture: scripts/regen-golden.sh, look at the frames, commit.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

void check_golden(const std::string& name, const std::string& backend) {
  const std::string dir = make_scratch_dir("golden-" + name + "-" + backend);
  std::filesystem::copy_file(source_path("tests/golden/" + name + ".toml"), dir + "/t.toml");
  const RunResult r = sdfreel("render t.toml --backend " + backend, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string suffix = backend == "cpu" ? "" : "." + backend;
  const std::string want = read_file(source_path("tests/golden/" + name + suffix + ".framemd5"));
  ASSERT_FALSE(want.empty()) << "no committed golden file; run scripts/regen-golden.sh";
  EXPECT_EQ(framemd5_data_lines(read_file(dir + "/out/frames.framemd5")), framemd5_data_lines(want))
      << "frames differ from the golden hashes; if the change is intended, run "
         "scripts/regen-golden.sh and look at the frames before committing";
}

TEST(Golden, SdfMorphCpu) {
  check_golden("sdf_morph_small", "cpu");
}

}  // namespace
}  // namespace sdfreel::test
