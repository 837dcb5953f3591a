// `sdfreel bench --whole-process`: each target rendered end to end by a fresh `sdfreel render`,
// at the timeline's own size unless --resolution is given; the table and whole_process.csv; a
// backend that cannot render is skipped and named; each backend's time against the CPU's.
#include "bench/whole_process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel::bench {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(BenchWholeProcess, RendersEachTargetAtItsOwnSizeAndWritesTheCsv) {
  const std::string dir = test::scratch_dir("bench-whole-process");
  const std::string timeline = dir + "/tiny.toml";
  write_file_atomic(timeline,
                    "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = 1.0\n"
                    "resolution = [24, 12]\nsamples = 1\n");
  const test::RunResult r = test::run_sdfreel("bench --whole-process '" + timeline +
                                              "' light_beams --frames 0,1 --backends cpu,nope "
                                              "--repetitions 2 --out '" +
                                              dir + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  // The timeline's own 24x12 and samples; the scene name at the bench's default size.
  EXPECT_NE(r.out.find("| tiny | 24x12 | 1 | 2 | cpu |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| light_beams | 320x180 | 4 | 2 | cpu |"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("skipping tiny on nope"), std::string::npos) << r.err;
  const std::string csv = read(dir + "/whole_process.csv");
  EXPECT_EQ(csv.rfind("scene,backend,width,height,samples,frames,wall_seconds,cpu_seconds\n", 0),
            0u)
      << csv;
  EXPECT_NE(csv.find("\ntiny,cpu,24,12,1,2,"), std::string::npos) << csv;
  // The renders wrote frames and hashes, as a user's render does.
  EXPECT_TRUE(std::filesystem::exists(dir + "/whole/tiny-cpu/frames.framemd5"));
  // --resolution applies to a timeline too when given.
  const test::RunResult sized =
      test::run_sdfreel("bench --whole-process '" + timeline +
                        "' --frames 0 --resolution 16x8 --repetitions 1 --out '" + dir + "'");
  ASSERT_EQ(sized.status, 0) << sized.out;
  EXPECT_NE(sized.out.find("| tiny | 16x8 | 1 | 1 | cpu |"), std::string::npos) << sized.out;
  std::filesystem::remove_all(dir);
}

TEST(BenchWholeProcess, NothingToTimeOrNoTargetIsAnError) {
  const std::string dir = test::scratch_dir("bench-whole-process-usage");
  EXPECT_EQ(test::run_sdfreel("bench --whole-process --out '" + dir + "'").status, 2);
  EXPECT_EQ(test::run_sdfreel("bench --whole-process light_beams --backends nope --frames 0 "
                              "--repetitions 1 --out '" +
                              dir + "'")
                .status,
            1);
  std::filesystem::remove_all(dir);
}

TEST(BenchWholeProcess, EachBackendAgainstTheCpusTime) {
  std::vector<WholeProcessRow> rows(3);
  rows[0] = {"museum", "cpu", 3, 1280, 720, "4", {2.0, 3.5}};
  rows[1] = {"museum", "gl", 3, 1280, 720, "4", {5.0, 9.0}};
  rows[2] = {"fur", "gl", 3, 1280, 720, "4", {4.0, 8.0}};  // no CPU row: no ratio
  const std::string t = format_whole_process_table(rows);
  EXPECT_NE(t.find("| museum | 1280x720 | 4 | 3 | cpu | 2.00 | 0.667 | 3.50 |  |"),
            std::string::npos)
      << t;
  EXPECT_NE(t.find("| museum | 1280x720 | 4 | 3 | gl | 5.00 | 1.667 | 9.00 | 2.50x |"),
            std::string::npos)
      << t;
  EXPECT_NE(t.find("| fur | 1280x720 | 4 | 3 | gl | 4.00 | 1.333 | 8.00 |  |"), std::string::npos)
      << t;
  EXPECT_EQ(whole_process_args("t.toml", "0-2", "", "gl", "o"),
            (std::vector<std::string>{"render", "t.toml", "--frames", "0-2", "--no-video",
                                      "--backend", "gl", "--out", "o"}));
}

}  // namespace
}  // namespace sdfreel::bench
