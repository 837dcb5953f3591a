// Issue 17, items 2-8 end to end: concurrent writers of one video, temporaries of killed renders,
// bad input found before anything is written, overflow-safe options, special files, damaged and
// foreign manifests. Each test failed on the build before the fixes (SDFREEL_TEST_BINARY runs them
// against another build).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli/folder_check.h"
#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  if (at == std::string::npos) throw std::logic_error("fixture lacks '" + from + "'");
  return s.replace(at, from.size(), to);
}

// Item 2: two renders with video into one folder (and encode beside a render) both publish a
// video that decodes to exactly the listed frames.
TEST(Reliability, ConcurrentRendersWithVideoPublishADecodableVideo) {
  if (!have_tool("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  const std::string dir = scratch_dir("rel-concurrent-video");
  write_file(dir + "/t.toml", small_timeline(6));
  const std::string bin = "'" + sdfreel_binary() + "' ";
  for (int round = 0; round < 3; ++round) {
    const RunResult r = run(bin + "render t.toml 2>e1 & a=$!; " + bin +
                                "render t.toml 2>e2 & b=$!; wait $a; echo $?; wait $b; echo $?",
                            dir);
    EXPECT_EQ(r.out, "0\n0\n") << read_file(dir + "/e1") << read_file(dir + "/e2");
    const FolderReport rep = check_output_folder(dir + "/out", "small.mkv");
    EXPECT_TRUE(rep.problems.empty()) << "round " << round << "\n" << rep.describe();
    EXPECT_TRUE(rep.has_video);
    EXPECT_EQ(rep.listed, 6);
  }
  // encode into the render's own video name while a render writes it.
  const RunResult r = run(bin + "render t.toml 2>e1 & a=$!; " + bin +
                              "encode out -o out/small.mkv --codec ffv1 2>e2 & b=$!; wait $a; echo "
                              "$?; wait $b; echo $?",
                          dir);
  EXPECT_EQ(r.out, "0\n0\n") << read_file(dir + "/e1") << read_file(dir + "/e2");
  const FolderReport rep = check_output_folder(dir + "/out", "small.mkv");
  EXPECT_TRUE(rep.problems.empty()) << rep.describe();
}

// Item 3: a render killed while its video is open leaves a temporary video; the next render
// (even --no-video) removes it at start-up.
TEST(Reliability, KilledRendersTemporaryVideoIsCleanedAtStartUp) {
  const std::string dir = scratch_dir("rel-kill-video");
  write_file(dir + "/t.toml", small_timeline(80));
  const RunResult killed =
      run("'" + sdfreel_binary() + "' render t.toml 2>/dev/null & pid=$!; " +
              "for i in $(seq 600); do n=$(ls -a out 2>/dev/null | grep -c 'small.*tmp'); " +
              "[ \"$n\" -ge 1 ] && break; sleep 0.02; done; kill -9 $pid; wait $pid; "
              "echo $?",
          dir);
  ASSERT_EQ(killed.out, "137\n") << "the render was not killed mid-run";
  ASSERT_FALSE(temporaries_in(dir + "/out").empty()) << "the kill left no temporary to clean";
  const RunResult r = run_sdfreel("render t.toml --resume --no-video --frames 0-1", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(temporaries_in(dir + "/out").empty())
      << "left: " << ::testing::PrintToString(temporaries_in(dir + "/out"));
}

// Item 4: bad output names are bad input: exit 2, FILE:LINE:COLUMN, nothing written.
TEST(Reliability, BadVideoNamesAndControlCharactersInDirAreRefusedBeforeWriting) {
  const std::string good = small_timeline(2);
  struct Case {
    const char* name;
    std::string timeline;
    const char* message;
  } cases[] = {
      {"unknown_extension", replace(good, "small.mkv", "small.xyz"), "unknown container"},
      {"no_extension", replace(good, "small.mkv", "small"), "unknown container"},
      {"mp4_with_ffv1", replace(good, "small.mkv", "small.mp4"), "cannot hold codec ffv1"},
      {"mov_with_ffv1", replace(good, "small.mkv", "small.mov"), "cannot hold codec ffv1"},
      {"video_in_subfolder", replace(good, "small.mkv", "sub/small.mkv"), "file name"},
      {"nul_in_dir", replace(good, "dir = \"out\"", "dir = \"out\\u0000x\""), "control character"},
      {"newline_in_video", replace(good, "small.mkv", "sm\\nall.mkv"), "control character"},
  };
  for (const Case& c : cases) {
    const std::string dir = scratch_dir(std::string("rel-bad-") + c.name);
    write_file(dir + "/t.toml", c.timeline);
    const RunResult r = run_sdfreel("render t.toml", dir);
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_TRUE(std::regex_search(r.err, std::regex("^t\\.toml:[0-9]+:[0-9]+: error: ")))
        << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    std::vector<std::string> made;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename() != "t.toml") made.push_back(e.path().filename().string());
    EXPECT_TRUE(made.empty()) << c.name << " wrote " << ::testing::PrintToString(made);
  }
  // encode -o with a container that cannot hold the codec: exit 2, no file.
  const std::string dir = scratch_dir("rel-bad-encode");
  write_file(dir + "/t.toml", small_timeline(2));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  const RunResult r = run_sdfreel("encode out -o v.mp4 --codec ffv1", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(temporaries_in(dir).empty() && !fs::exists(dir + "/v.mp4"));
}

// Item 5: numbers that do not fit are refused (exit 2), never wrapped; huge shard indices work.
TEST(Reliability, CommandLineNumbersDoNotOverflow) {
  const std::string dir = scratch_dir("rel-overflow");
  write_file(dir + "/t.toml", small_timeline(4));
  for (const char* args :
       {"--resolution 4294967298x2", "--resolution 4294967360x36",
        "--resolution 18446744073709551680x2", "--resolution 64x-36", "--resolution 0x0x0",
        "--shard 1/18446744073709551617", "--shard 99999999999999999999/3", "--shard -1/2",
        "--shard 1/+2", "--frames 0-99999999999", "--frames 4294967296"}) {
    const RunResult r = run_sdfreel(std::string("render t.toml --no-video ") + args, dir);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out")) << args << " wrote the output folder";
  }
  // The last of 2^62 shards of 4 frames is frame 3; its neighbour holds no frame.
  RunResult r =
      run_sdfreel("render t.toml --no-video --shard 4611686018427387903/4611686018427387904", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/frames/00003.png"));
  EXPECT_FALSE(fs::exists(dir + "/out/frames/00000.png"));
  r = run_sdfreel("render t.toml --no-video --shard 4611686018427387902/4611686018427387904", dir);
  EXPECT_EQ(r.status, 0) << r.err;
}

// Item 7: FIFOs and devices never block or read without limit.
TEST(Reliability, FifosAndDevicesAreRefusedAtOnce) {
  const std::string dir = scratch_dir("rel-fifo");
  ASSERT_EQ(::mkfifo((dir + "/fifo.toml").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((dir + "/fifo.json").c_str(), 0644), 0);
  write_file(dir + "/t.toml", small_timeline(2));
  // `timeout` turns a hang into status 124 instead of a stuck test.
  auto with_timeout = [&](const std::string& args) {
    return run("timeout 20 '" + sdfreel_binary() + "' " + args, dir);
  };
  RunResult r = with_timeout("render fifo.toml");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("fifo.toml"), std::string::npos) << r.err;
  r = with_timeout("render /dev/zero");
  EXPECT_EQ(r.status, 2) << r.err;
  r = with_timeout("verify t.toml --manifest fifo.json");
  EXPECT_EQ(r.status, 2) << r.err;
  r = with_timeout("verify t.toml --manifest /dev/zero");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// Item 8: damaged, malformed and out-of-range manifests.
TEST(Reliability, DamagedManifestDoesNotStopResume) {
  const std::string dir = scratch_dir("rel-damaged");
  write_file(dir + "/t.toml", small_timeline(3));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  write_file(dir + "/out/manifest.json", "{\"format\": \"sdfreel-manifest-1\", \"frames\": [");
  const RunResult r = run_sdfreel("render t.toml --no-video --resume", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("damaged"), std::string::npos) << r.err;
  const FolderReport rep = check_output_folder(dir + "/out", "");
  EXPECT_TRUE(rep.problems.empty()) << rep.describe();
  EXPECT_EQ(rep.listed, 3);
}

TEST(Reliability, MalformedManifestIsExitTwoLikeAMissingOne) {
  const std::string dir = scratch_dir("rel-malformed");
  write_file(dir + "/t.toml", small_timeline(2));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  EXPECT_EQ(run_sdfreel("verify t.toml --manifest missing.json", dir).status, 2);
  write_file(dir + "/bad.json", "{ not json");
  EXPECT_EQ(run_sdfreel("verify t.toml --manifest bad.json", dir).status, 2);
  fs::create_directories(dir + "/enc");
  write_file(dir + "/enc/manifest.json", "[1, 2");
  EXPECT_EQ(run_sdfreel("encode enc -o v.mkv --codec ffv1", dir).status, 2);
}

TEST(Reliability, ManifestFrameIndexBeyondIntIsRefusedNotWrapped) {
  const std::string dir = scratch_dir("rel-index");
  write_file(dir + "/t.toml", small_timeline(2));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  // Frame 0's entry renamed to index 2^40 (which an int wraps to 0): frame 0 is no longer listed.
  auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  m["frames"][0]["index"] = int64_t(1) << 40;
  write_file(dir + "/out/manifest.json", m.dump());
  const RunResult r = run_sdfreel("verify t.toml --manifest out/manifest.json --frames 0", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("1099511627776"), std::string::npos) << r.err;
}

TEST(Reliability, RenderWithOtherSettingsIntoALiveFolderIsRefused) {
  const std::string dir = scratch_dir("rel-foreign");
  write_file(dir + "/t.toml", small_timeline(200));
  const std::string bin = "'" + sdfreel_binary() + "' ";
  // Shard 0 runs; shard 1 with other samples starts while it is live.
  const RunResult r = run(
      bin + "render t.toml --no-video --shard 0/2 2>e1 & a=$!; " +
          "for i in $(seq 600); do [ -s out/manifest.journal ] || grep -q '\"index\"' "
          "out/manifest.json 2>/dev/null && break; sleep 0.02; done; " +
          bin + "render t.toml --no-video --shard 1/2 --samples 2 2>e2; echo $?; kill $a; wait $a",
      dir);
  EXPECT_EQ(r.out, "2\n") << read_file(dir + "/e2");
  EXPECT_NE(read_file(dir + "/e2").find("other settings"), std::string::npos)
      << read_file(dir + "/e2");
  // The live render's frames are all still listed and intact.
  const FolderReport rep = check_output_folder(dir + "/out", "", true);
  EXPECT_TRUE(rep.problems.empty()) << rep.describe();
  EXPECT_GT(rep.listed, 0);
}

}  // namespace
}  // namespace sdfreel::test
