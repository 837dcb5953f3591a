// [output] audio end to end: render muxes it, the manifest names its hash, encode after shards
// adds it the same way (and refuses a changed file), a missing file is exit 2 before anything.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/harness.h"
#include "support/wav_file.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

std::string with_audio(const std::string& audio_keys) {
  std::string t = small_timeline(5, "h264", "v.mp4");
  const std::string codec = "codec = \"h264\"\n";
  return t.replace(t.find(codec), codec.size(), codec + audio_keys);
}

// "video,audio" for a file with both streams.
std::string stream_types(const std::string& path) {
  const RunResult r =
      run("ffprobe -v error -show_entries stream=codec_type -of csv=p=0 " + path + " | paste -sd,");
  return r.out.substr(0, r.out.find('\n'));
}

TEST(Soundtrack, RenderMuxesItAndEncodeAddsItAfterShards) {
  if (!have_tool("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  const std::string dir = scratch_dir("soundtrack");
  write_tone_wav(dir + "/tone.wav", 2.0, 48000, 0.0);
  write_file(dir + "/t.toml", with_audio("audio = \"tone.wav\"\naudio_offset = 0.25\n"));
  RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(stream_types(dir + "/out/v.mp4"), "video,audio");
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m["audio"]["sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(m["audio"]["offset"], 0.25);
  // The audio changes no frame: the same hashes as without it.
  write_file(dir + "/plain.toml", small_timeline(5, "h264", "v.mp4"));
  ASSERT_EQ(run_sdfreel("render plain.toml --out plain", dir).status, 0);
  EXPECT_EQ(read_file(dir + "/plain/frames.framemd5"), read_file(dir + "/out/frames.framemd5"));

  ASSERT_EQ(run_sdfreel("render t.toml --no-video --out shards", dir).status, 0);
  r = run_sdfreel("encode shards -o w.mp4", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(stream_types(dir + "/w.mp4"), "video,audio");
  write_tone_wav(dir + "/tone.wav", 2.0, 48000, 0.5);  // another file under the same name
  r = run_sdfreel("encode shards -o x.mp4", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("changed since the render"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.mp4"));
}

TEST(Soundtrack, AMissingOrUndecodableFileIsExitTwoBeforeAnything) {
  const std::string dir = scratch_dir("soundtrack-bad");
  write_file(dir + "/t.toml", with_audio("audio = \"none.flac\"\n"));
  RunResult r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("t.toml:14:9: error: output.audio: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  write_file(dir + "/text.wav", "not audio at all");
  write_file(dir + "/t.toml", with_audio("audio = \"text.wav\"\n"));
  r = run_sdfreel("render t.toml --no-video", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("text.wav"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  // A FIFO would block the decoder's open for ever: refused at once, unread.
  ASSERT_EQ(run("mkfifo pipe.wav", dir).status, 0);
  write_file(dir + "/t.toml", with_audio("audio = \"pipe.wav\"\n"));
  r = run_sdfreel("render t.toml --no-video", dir, "timeout 60 ");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  write_tone_wav(dir + "/tone.wav", 1.0, 48000, 0.0);
  write_file(dir + "/t.toml", with_audio("audio = \"tone.wav\"\n"));
  r = run_sdfreel("render t.toml --video loop.webp", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("a .webp video holds no sound"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  write_file(dir + "/t.toml", with_audio("audio_fade = 1.0\n"));
  r = run_sdfreel("check t.toml", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("output.audio_fade needs output.audio"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sdfreel::test
