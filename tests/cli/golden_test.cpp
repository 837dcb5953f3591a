// Golden hashes: small renders must reproduce the committed frames.framemd5 bit for bit.
// After an intended change of the picture: scripts/regen-golden.sh, look at the frames, commit.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

// Renders tests/golden/NAME.toml with `backend` and compares with the committed hashes of
// `golden_backend` (NAME.framemd5 for cpu, NAME.<backend>.framemd5 otherwise): a backend that is
// bit-identical to the CPU backend is held to the CPU's file.
void check_golden(const std::string& name, const std::string& backend,
                  const std::string& golden_backend) {
  const std::string dir = make_scratch_dir("golden-" + name + "-" + backend);
  std::filesystem::copy_file(source_path("tests/golden/" + name + ".toml"), dir + "/t.toml");
  const RunResult r = sdfreel("render t.toml --backend " + backend, dir);
  // A machine (or build) without OSMesa cannot run the osmesa backend at all: nothing to compare.
  if (r.status != 0 && (r.err.find("cannot start the osmesa backend") != std::string::npos ||
                        r.err.find("osmesa backend is not built") != std::string::npos))
    GTEST_SKIP() << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string suffix = golden_backend == "cpu" ? "" : "." + golden_backend;
  const std::string want = read_file(source_path("tests/golden/" + name + suffix + ".framemd5"));
  ASSERT_FALSE(want.empty()) << "no committed golden file; run scripts/regen-golden.sh";
  EXPECT_EQ(framemd5_data_lines(read_file(dir + "/out/frames.framemd5")), framemd5_data_lines(want))
      << "frames differ from the golden hashes; if the change is intended, run "
         "scripts/regen-golden.sh and look at the frames before committing";
}

void check_golden(const std::string& name, const std::string& backend) {
  check_golden(name, backend, backend);
}

TEST(Golden, SdfMorphCpu) {
  check_golden("sdf_morph_small", "cpu");
}

TEST(Golden, LanternFestivalCpu) {
  check_golden("lantern_festival_small", "cpu");
}

// The GLSL twin renders the same bits as the C++ scene: held to the CPU backend's hashes.
TEST(Golden, LanternFestivalOsmesaMatchesCpuHashes) {
  check_golden("lantern_festival_small", "osmesa", "cpu");
}

TEST(Golden, WaterLilyCpu) {
  check_golden("water_lily/water_lily_small", "cpu");
}

// The GLSL twin renders the same bits as the C++ scene: held to the CPU backend's hashes.
TEST(Golden, WaterLilyOsmesaMatchesCpuHashes) {
  check_golden("water_lily/water_lily_small", "osmesa", "cpu");
}

}  // namespace
}  // namespace sdfreel::test
