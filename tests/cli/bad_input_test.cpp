// End-to-end contract for bad input: exit 2, "FILE:LINE:COLUMN: error: WHAT", nothing on disk.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

struct BadCase {
  const char* name;
  std::string timeline;
  const char* message;  // a piece of the expected message
  const char* args = "";
};

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  if (at == std::string::npos) throw std::logic_error("fixture lacks '" + from + "'");
  return s.replace(at, from.size(), to);
}

std::vector<BadCase> bad_cases() {
  const std::string good = small_timeline(4);
  return {
      {"syntax", good + "\n[broken\n", ""},
      {"unknown_key", replace(good, "samples = 1", "sample = 1"), "samples"},
      {"wrong_type", replace(good, "samples = 1", "samples = \"four\""), "samples"},
      {"nan", replace(good, "duration = ", "duration = nan # "), "duration"},
      {"fps_zero", replace(good, "fps = 10", "fps = 0"), "fps"},
      {"duration_negative", replace(good, "duration = ", "duration = -"), "duration"},
      {"resolution", replace(good, "[64, 36]", "[64, 0]"), "resolution"},
      {"fov", replace(good, "fov = 40.0", "fov = 180.0"), "fov"},
      {"position_is_target",
       replace(good, "position = [0.0, 1.5, -4.0]", "position = [0.0, 0.6, 0.0]"), "target"},
      {"unknown_scene", replace(good, "sdf_morph", "sdf_morf"), "sdf_morf"},
      {"unknown_param", replace(good, "morph_period = 2.0", "morph_perod = 2.0"), "morph_period"},
      {"param_range", replace(good, "morph_period = 2.0", "morph_period = -5.0"), "morph_period"},
      {"unknown_codec", replace(good, "codec = \"ffv1\"", "codec = \"vp8\""), "vp8"},
      {"odd_h264",
       replace(replace(good, "codec = \"ffv1\"", "codec = \"h264\""), "[64, 36]", "[63, 36]"),
       "64x36"},
      {"unknown_view", good + "[color]\nview = \"Filmic\"\n", "Filmic"},
      {"samples", replace(good, "samples = 1", "samples = 2000"), "samples"},
      {"keys_order", replace(good, "t = 2.0", "t = 0.0"), "strictly increase"},
      {"override_resolution", good, "", "--resolution 20000x10"},
  };
}

TEST(BadInput, ExitsTwoWithLocationAndWritesNothing) {
  for (const BadCase& c : bad_cases()) {
    const std::string dir = scratch_dir(std::string("bad-") + c.name);
    write_file(dir + "/t.toml", c.timeline);
    const RunResult r = run_sdfreel(std::string("render t.toml ") + c.args, dir);
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_TRUE(std::regex_search(r.err, std::regex("^t\\.toml:([0-9]+:[0-9]+:)? error: ")))
        << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out")) << c.name << ": output folder was created";
    // Only the line-less override case may omit line:column.
    if (std::string(c.args).empty()) {
      EXPECT_TRUE(std::regex_search(r.err, std::regex("^t\\.toml:[0-9]+:[0-9]+: error: ")))
          << c.name << ": " << r.err;
    }
  }
}

TEST(BadInput, NonUtf8AndHugeFilesAreRefused) {
  const std::string dir = scratch_dir("bad-bytes");
  write_file(dir + "/t.toml", small_timeline(2) + "# \xff\xfe\n");
  EXPECT_EQ(run_sdfreel("render t.toml", dir).status, 2);
  write_file(dir + "/big.toml", small_timeline(2) + std::string(17 << 20, '#'));
  EXPECT_EQ(run_sdfreel("render big.toml", dir).status, 2);
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(BadInput, UnknownCommandLineOptionsExitTwo) {
  EXPECT_EQ(run_sdfreel("render").status, 2);
  EXPECT_EQ(run_sdfreel("render x.toml --bogus").status, 2);
  EXPECT_EQ(run_sdfreel("frobnicate").status, 2);
  EXPECT_EQ(run_sdfreel("scenes no_such_scene").status, 2);
  // A near miss gets the same "did you mean" as in a timeline.
  const RunResult r = run_sdfreel("scenes water_lilly");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown scene 'water_lilly'; did you mean 'water_lily'?"),
            std::string::npos)
      << r.err;
}

// h264's even sides matter only where a video is made: --no-video, a partial range and a still
// take an odd size; the render that would write the video refuses, pointing at the resolution.
TEST(BadInput, OddSizeIsRefusedExactlyWhenAVideoIsMade) {
  const std::string dir = scratch_dir("odd-size");
  write_file(dir + "/t.toml", replace(small_timeline(3, "h264", "v.mp4"), "[64, 36]", "[63, 36]"));
  const RunResult whole = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(whole.status, 2);
  EXPECT_NE(whole.err.find("t.toml:5:14: error: resolution 63x36 has an odd side"),
            std::string::npos)
      << whole.err;
  EXPECT_EQ(run_sdfreel("check t.toml", dir).status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir + "/out"));
  for (const char* ok : {"render t.toml --no-video --out a", "render t.toml --frames 0-1 --out b",
                         "still t.toml --time 0 -o s.png", "check t.toml --no-video"}) {
    const RunResult r = run_sdfreel(ok, dir);
    EXPECT_EQ(r.status, 0) << ok << ": " << r.err;
  }
  // A size from the command line is held to the same rule, without a place in the file.
  const RunResult opt = run_sdfreel("render t.toml --resolution 65x36", dir);
  EXPECT_EQ(opt.status, 2);
  EXPECT_NE(opt.err.find("t.toml: error: resolution 65x36 has an odd side"), std::string::npos)
      << opt.err;
}

// Mistakes whose first answers were a library's words: each now says what to do, exit 2.
TEST(BadInput, CommonMistakesGetAnAnswerThatSaysWhatToDo) {
  const std::string dir = scratch_dir("mistakes");
  write_file(dir + "/t.toml", small_timeline(3));
  write_file(dir + "/afile", "not a folder");
  for (const char* cmd : {"render t.toml --out afile", "render t.toml --out afile/inner",
                          "check t.toml --out afile"}) {
    const RunResult r = run_sdfreel(cmd, dir);
    EXPECT_EQ(r.status, 2) << cmd;
    EXPECT_NE(r.err.find("is a file, not a folder; choose another folder with --out"),
              std::string::npos)
        << cmd << ": " << r.err;
  }
  EXPECT_EQ(read_file(dir + "/afile"), "not a folder");

  const RunResult frames = run_sdfreel("still t.toml --frames 0 -o x.png", dir);
  EXPECT_EQ(frames.status, 2);
  EXPECT_NE(frames.err.find("use `sdfreel render TIMELINE --frames 0`"), std::string::npos)
      << frames.err;
  const RunResult no_time = run_sdfreel("still t.toml -o x.png", dir);
  EXPECT_EQ(no_time.status, 2);
  EXPECT_NE(no_time.err.find("--time SECONDS is required"), std::string::npos) << no_time.err;

  write_file(dir + "/open.toml", "[video]\nscene = \"sdf_morph\nfps = 10\n");
  const RunResult open = run_sdfreel("check open.toml", dir);
  EXPECT_EQ(open.status, 2);
  EXPECT_NE(open.err.find("open.toml:2:19: error: a string is not closed"), std::string::npos)
      << open.err;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
}

// A frame too large for the memory this process may have is refused before anything is written,
// with both sizes (it was std::bad_alloc, exit 1, after the render had started).
TEST(BadInput, AFrameLargerThanTheMemoryIsRefusedWithTheSizeItNeeds) {
  const std::string dir = scratch_dir("too-big");
  write_file(dir + "/t.toml", small_timeline(2));
  for (const char* cmd : {"render t.toml --resolution 16384x16384",
                          "still t.toml --time 0 --resolution 16384x16384 -o big.png",
                          "check t.toml --resolution 16384x16384"}) {
    const RunResult r = run("ulimit -v 3000000; '" + sdfreel_binary() + "' " + cmd, dir);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("a 16384x16384 frame needs at least 9.0 GiB (its images alone), and "
                         "this process may have 2.9 GiB (ulimit -v)"),
              std::string::npos)
        << cmd << ": " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/out"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/big.png"));
  // Where no frame of that size is made here, nothing is refused: a sheet's tiles are small, and
  // slurm's frames are rendered on the nodes, not on the submit host.
  write_file(dir + "/big.toml", replace(small_timeline(2), "[64, 36]", "[16384, 16384]"));
  for (const char* cmd : {"sheet big.toml -o sheet.png --count 2 --tile-width 32",
                          "slurm big.toml --tasks 2 --dry-run"}) {
    const RunResult r = run("ulimit -v 3000000; '" + sdfreel_binary() + "' " + cmd, dir);
    EXPECT_EQ(r.status, 0) << cmd << ": " << r.err;
  }
}

}  // namespace
}  // namespace sdfreel::test
