// End-to-end: frames, manifest, framemd5 and video of a small render, and their determinism.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/harness.h"
#include "io/manifest.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

TEST(Render, WritesFramesManifestFramemd5AndVideo) {
  const std::string dir = scratch_dir("render-basic");
  write_file(dir + "/t.toml", small_timeline(4));
  const RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (int i = 0; i < 4; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "/out/frames/%05d.", i);
    EXPECT_TRUE(fs::exists(dir + name + "png")) << name;
    EXPECT_TRUE(fs::exists(dir + name + "exr")) << name;
  }
  EXPECT_TRUE(fs::exists(dir + "/out/small.mkv"));
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m["frames"].size(), 4u);
  EXPECT_EQ(m["backend"], "cpu");
  EXPECT_EQ(m["resolution"][0], 64);
  EXPECT_EQ(m["timeline"]["sha256"].get<std::string>().size(), 64u);
  EXPECT_TRUE(m["versions"].contains("opencolorio"));
  const auto lines = framemd5_data_lines(read_file(dir + "/out/frames.framemd5"));
  ASSERT_EQ(lines.size(), 4u);
  // Non-terminal stderr: one parseable line per frame.
  EXPECT_NE(r.err.find("frame 4/4 done in "), std::string::npos) << r.err;
}

// A render ends with a line that says what it did, also without a video; an empty shard says so.
TEST(Render, EndsWithASummaryLine) {
  const std::string dir = scratch_dir("render-summary");
  write_file(dir + "/t.toml", small_timeline(3));
  RunResult r = run_sdfreel("render t.toml --no-video", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("done: 3 frames in out (3 rendered, 0 kept from before) in "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(" s; no video (--no-video)\n"), std::string::npos) << r.err;
  r = run_sdfreel("render t.toml --resume --frames 1-2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("done: 2 frames in out (0 rendered, 2 kept from before)"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("; no video (a partial frame range)\n"), std::string::npos) << r.err;
  r = run_sdfreel("render t.toml --shard 0/31 --no-video --out empty", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("--shard 0/31 of 3 frames selects none: nothing to render"),
            std::string::npos)
      << r.err;
}

TEST(Render, Framemd5MatchesStockFfmpegOnPngsAndOnFfv1Video) {
  if (!have_tool("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  const std::string dir = scratch_dir("render-ffmpeg");
  write_file(dir + "/t.toml", small_timeline(3));
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  const auto ours = framemd5_data_lines(read_file(dir + "/out/frames.framemd5"));
  const RunResult png =
      run("ffmpeg -v error -i out/frames/%05d.png -pix_fmt rgb48le -fflags +bitexact -f framemd5 -",
          dir);
  ASSERT_EQ(png.status, 0) << png.err;
  EXPECT_EQ(framemd5_data_lines(png.out), ours);
  const RunResult mkv =
      run("ffmpeg -v error -i out/small.mkv -pix_fmt rgb48le -fflags +bitexact -f framemd5 -", dir);
  ASSERT_EQ(mkv.status, 0) << mkv.err;
  EXPECT_EQ(framemd5_data_lines(mkv.out), ours);
}

TEST(Render, SameHashesForOneTwoAndFourThreads) {
  std::vector<std::string> results;
  for (int threads : {1, 2, 4}) {
    const std::string dir = scratch_dir("render-threads-" + std::to_string(threads));
    write_file(dir + "/t.toml", small_timeline(3));
    ASSERT_EQ(
        run_sdfreel("render t.toml --no-video --threads " + std::to_string(threads), dir).status,
        0);
    results.push_back(read_file(dir + "/out/frames.framemd5"));
  }
  EXPECT_EQ(results[0], results[1]);
  EXPECT_EQ(results[0], results[2]);
}

TEST(Render, ResumeAfterPartialRenderEqualsFullRender) {
  const std::string full = scratch_dir("render-full");
  write_file(full + "/t.toml", small_timeline(6));
  ASSERT_EQ(run_sdfreel("render t.toml", full).status, 0);

  const std::string part = scratch_dir("render-resume");
  write_file(part + "/t.toml", small_timeline(6));
  ASSERT_EQ(run_sdfreel("render t.toml --frames 0-2", part).status, 0);
  EXPECT_FALSE(fs::exists(part + "/out/small.mkv"));  // partial range: no video
  // A damaged frame on disk must be rendered again, not kept.
  write_file(part + "/out/frames/00001.png", "not a png");
  const RunResult r = run_sdfreel("render t.toml --resume", part);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(" kept (frame"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(part + "/out/frames.framemd5"), read_file(full + "/out/frames.framemd5"));
  EXPECT_EQ(read_file(part + "/out/frames/00001.png"), read_file(full + "/out/frames/00001.png"));
  EXPECT_EQ(read_file(part + "/out/small.mkv"), read_file(full + "/out/small.mkv"));
}

// A comment, whitespace or key order changes no pixel: resume keeps the frames and verify passes;
// a changed value makes them foreign. The manifest keeps both hashes.
TEST(Render, EditsThatChangeNoPixelKeepTheFrames) {
  const std::string dir = scratch_dir("render-parsed-hash");
  const std::string timeline = small_timeline(3);
  write_file(dir + "/t.toml", timeline);
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  write_file(dir + "/t.toml", "# the same render, written otherwise\n" + timeline + "\n\n");
  const RunResult resumed = run_sdfreel("render t.toml --no-video --resume", dir);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("(0 rendered, 3 kept from before)"), std::string::npos) << resumed.err;
  const RunResult verified = run_sdfreel("verify t.toml --manifest out/manifest.json", dir);
  EXPECT_EQ(verified.status, 0) << verified.err;
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m["timeline"]["sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(m["timeline"]["parsed_sha256"].get<std::string>().size(), 64u);

  std::string changed = timeline;
  changed.replace(changed.find("morph_period = 2.0"), 18, "morph_period = 2.5");
  write_file(dir + "/t.toml", changed);
  const RunResult again = run_sdfreel("render t.toml --no-video --resume", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("(3 rendered, 0 kept from before)"), std::string::npos) << again.err;
}

// A render of other settings into a finished folder replaces the old render whole: its frames
// beyond the new range and its video go, so nothing stale looks current.
TEST(Render, ARenderOfOtherSettingsReplacesTheOldOneInItsFolder) {
  const std::string dir = scratch_dir("render-replace");
  write_file(dir + "/a.toml", small_timeline(6));
  ASSERT_EQ(run_sdfreel("render a.toml --out out", dir).status, 0);
  ASSERT_TRUE(fs::exists(dir + "/out/small.mkv"));
  std::string other = small_timeline(3, "ffv1", "b.mkv");
  other.replace(other.find("morph_period = 2.0"), 18, "morph_period = 3.0");
  write_file(dir + "/b.toml", other);
  const RunResult r = run_sdfreel("render b.toml --out out --no-video", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("held a render of other settings; its 12 frame files and small.mkv were "
                       "removed"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out/small.mkv"));
  for (const char* gone : {"00003.png", "00005.exr"})
    EXPECT_FALSE(fs::exists(dir + "/out/frames/" + std::string(gone))) << gone;
  EXPECT_TRUE(fs::exists(dir + "/out/frames/00002.png"));
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m.at("frames").size(), 3u);
  // The same settings again: nothing is removed.
  const RunResult same = run_sdfreel("render b.toml --out out --no-video --resume", dir);
  EXPECT_EQ(same.err.find("held a render"), std::string::npos) << same.err;
}

TEST(Render, ShardsThenEncodeEqualOneRender) {
  const std::string full = scratch_dir("render-one");
  write_file(full + "/t.toml", small_timeline(5));
  ASSERT_EQ(run_sdfreel("render t.toml", full).status, 0);

  const std::string sharded = scratch_dir("render-shards");
  write_file(sharded + "/t.toml", small_timeline(5));
  ASSERT_EQ(run_sdfreel("render t.toml --shard 1/2", sharded).status, 0);
  // Encoding with a frame missing fails (exit 1) and names it.
  const RunResult early = run_sdfreel("encode out -o early.mkv --codec ffv1", sharded);
  EXPECT_EQ(early.status, 1);
  EXPECT_NE(early.err.find("frame 0 "), std::string::npos) << early.err;
  ASSERT_EQ(run_sdfreel("render t.toml --shard 0/2", sharded).status, 0);
  EXPECT_EQ(read_file(sharded + "/out/frames.framemd5"), read_file(full + "/out/frames.framemd5"));
  const RunResult enc = run_sdfreel("encode out -o joined.mkv --codec ffv1", sharded);
  ASSERT_EQ(enc.status, 0) << enc.err;
  EXPECT_EQ(read_file(sharded + "/joined.mkv"), read_file(full + "/out/small.mkv"));
}

TEST(Render, EncodeRefusesAFrameThatDiffersFromTheManifest) {
  const std::string dir = scratch_dir("render-tamper");
  write_file(dir + "/t.toml", small_timeline(2));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  fs::copy_file(dir + "/out/frames/00000.png", dir + "/out/frames/00001.png",
                fs::copy_options::overwrite_existing);
  const RunResult r = run_sdfreel("encode out -o v.mkv --codec ffv1", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("frame 1"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/v.mkv"));
}

TEST(Render, KilledRenderLeavesOnlyCompleteFramesListedInTheManifest) {
  const std::string dir = scratch_dir("render-kill");
  write_file(dir + "/t.toml", small_timeline(120));
  // SIGKILL the render as soon as three frames are listed (manifest.journal holds the frames
  // finished since manifest.json was last rebuilt): mid-run however fast the machine.
  const RunResult killed = run(
      "'" + std::string(SDFREEL_BINARY) + "' render t.toml --no-video & pid=$!; " +
          "for i in $(seq 600); do n=$(grep -c '\"index\"' out/manifest.journal 2>/dev/null); " +
          "[ \"${n:-0}\" -ge 3 ] && break; sleep 0.02; done; kill -9 $pid; wait $pid; echo $?",
      dir);
  EXPECT_EQ(killed.out, "137\n") << "the render was not killed: " << killed.err;
  const auto m = read_manifest(dir + "/out/manifest.json");
  ASSERT_TRUE(m);
  ASSERT_LT(m->frames.size(), 120u) << "render finished before the kill";
  ASSERT_GE(m->frames.size(), 3u);
  // Every listed frame is on disk, complete and matches its hash; the resume finishes the job.
  const RunResult r = run_sdfreel("render t.toml --no-video --resume", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  size_t kept = 0;
  for (size_t pos = 0; (pos = r.err.find(" kept (frame", pos)) != std::string::npos; ++pos) ++kept;
  EXPECT_EQ(kept, m->frames.size());
  for (const auto& entry : fs::directory_iterator(dir + "/out/frames")) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find("tmp"), std::string::npos) << "temporary file left: " << name;
  }
}

TEST(Still, WritesOnePngAndOneExr) {
  const std::string dir = scratch_dir("still");
  write_file(dir + "/t.toml", small_timeline(4));
  ASSERT_EQ(run_sdfreel("still t.toml --time 0.25 -o a.png", dir).status, 0);
  ASSERT_EQ(run_sdfreel("still t.toml --time 0.25 -o a.exr", dir).status, 0);
  EXPECT_GT(fs::file_size(dir + "/a.png"), 100u);
  EXPECT_GT(fs::file_size(dir + "/a.exr"), 100u);
  EXPECT_EQ(run_sdfreel("still t.toml --time 0.25 -o a", dir).status, 2);  // no format named
}

// A built-in scene's still and render never open OpenImageIO (some 250 shared libraries): only a
// shader's image channels do (docs/startup-and-io.md).
TEST(Still, NeverLoadsOpenImageIO) {
  const std::string dir = scratch_dir("still_libraries");
  write_file(dir + "/t.toml", small_timeline(2));
  for (const std::string args :
       {"--version", "still t.toml --time 0.25 -o a.png", "render t.toml"}) {
    const RunResult r = run_sdfreel(args, dir, "LD_DEBUG=files ");
    ASSERT_EQ(r.status, 0) << args;
    EXPECT_NE(r.err.find("libpng"), std::string::npos) << "LD_DEBUG reports libraries: " << args;
    EXPECT_EQ(r.err.find("libOpenImageIO"), std::string::npos) << args;
  }
}

// libav's encoders are in sdfreel's video module (io/video_module.h): a run that writes no
// video never loads them (127 libraries, 31 ms of each start); a render with a video does.
TEST(Render, OpensTheVideoModuleOnlyForAVideo) {
  const std::string dir = scratch_dir("video_module_libraries");
  write_file(dir + "/t.toml", small_timeline(2));
  for (const std::string args :
       {"--version", "still t.toml --time 0.25 -o a.png", "render t.toml --no-video"}) {
    const RunResult r = run_sdfreel(args, dir, "LD_DEBUG=files ");
    ASSERT_EQ(r.status, 0) << args;
    EXPECT_NE(r.err.find("libpng"), std::string::npos) << "LD_DEBUG reports libraries: " << args;
    EXPECT_EQ(r.err.find("sdfreel_video_av"), std::string::npos) << args;
    EXPECT_EQ(r.err.find("libavcodec"), std::string::npos) << args;
    EXPECT_EQ(r.err.find("libavformat"), std::string::npos) << args;
  }
  const RunResult video = run_sdfreel("render t.toml", dir, "LD_DEBUG=files ");
  ASSERT_EQ(video.status, 0) << video.err.substr(video.err.size() > 2000 ? video.err.size() - 2000
                                                                         : 0);
  EXPECT_NE(video.err.find("sdfreel_video_av.so"), std::string::npos);
  EXPECT_NE(video.err.find("libavcodec"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/out/small.mkv"));
}

TEST(Verify, PassesOnItsOwnRenderAndFailsOnADifferentFrame) {
  const std::string dir = scratch_dir("verify");
  write_file(dir + "/t.toml", small_timeline(3));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  const RunResult ok = run_sdfreel("verify t.toml --manifest out/manifest.json", dir);
  EXPECT_EQ(ok.status, 0) << ok.err;
  // Swap two frames' hashes in the manifest: verify must name frame 0 and write a diff image.
  auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  std::swap(m["frames"][0]["display_md5"], m["frames"][1]["display_md5"]);
  write_file(dir + "/out/manifest.json", m.dump(2));
  const RunResult bad = run_sdfreel("verify t.toml --manifest out/manifest.json", dir);
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("frame 0 differs"), std::string::npos) << bad.err;
  EXPECT_TRUE(fs::exists(dir + "/out/verify-00000-diff.png"));
}

}  // namespace
}  // namespace sdfreel::test
