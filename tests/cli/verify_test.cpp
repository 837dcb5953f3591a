// `sdfreel verify` takes the golden people keep: a manifest.json, sdfreel's frames.framemd5, or a
// framemd5 made by stock ffmpeg from the PNGs; anything else is bad input (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "cli/harness.h"
#include "io/frame_files.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// Renders three small frames into DIR/out once per test.
std::string rendered(const std::string& name) {
  const std::string dir = scratch_dir(name);
  write_file(dir + "/t.toml", small_timeline(3));
  EXPECT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  return dir;
}

// Replaces the hash of data line `line` (0-based) with another valid one.
std::string with_hash_changed(const std::string& framemd5, int line) {
  std::string out;
  int data = 0;
  size_t pos = 0;
  while (pos < framemd5.size()) {
    size_t end = framemd5.find('\n', pos);
    std::string l = framemd5.substr(pos, end - pos);
    if (!l.empty() && l[0] != '#' && data++ == line)
      l = l.substr(0, l.size() - 32) + "0123456789abcdef0123456789abcdef";
    out += l + "\n";
    pos = end == std::string::npos ? framemd5.size() : end + 1;
  }
  return out;
}

TEST(VerifyFramemd5, AcceptsTheFramemd5SdfreelWrote) {
  const std::string dir = rendered("verify-own-framemd5");
  const RunResult r = run_sdfreel("verify t.toml --manifest out/frames.framemd5", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("verified 3 frames"), std::string::npos) << r.err;
}

TEST(VerifyFramemd5, AcceptsAFramemd5OfStockFfmpegFromThePngs) {
  ASSERT_TRUE(have_tool("ffmpeg")) << "scripts/install-deps.sh installs ffmpeg for the tests";
  const std::string dir = rendered("verify-ffmpeg-framemd5");
  const RunResult ff =
      run("ffmpeg -v error -i out/frames/%05d.png -pix_fmt rgb48le -fflags +bitexact -f framemd5 "
          "golden.framemd5",
          dir);
  ASSERT_EQ(ff.status, 0) << ff.err;
  const RunResult r = run_sdfreel("verify t.toml --manifest golden.framemd5", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("verified 3 frames"), std::string::npos) << r.err;

  // The same file with frame 1's hash changed must fail on frame 1.
  write_file(dir + "/bad.framemd5", with_hash_changed(read_file(dir + "/golden.framemd5"), 1));
  const RunResult bad = run_sdfreel("verify t.toml --manifest bad.framemd5", dir);
  EXPECT_EQ(bad.status, 1) << bad.err;
  EXPECT_NE(bad.err.find("frame 1 differs"), std::string::npos) << bad.err;
}

TEST(VerifyFramemd5, AFramemd5OfAnotherResolutionFailsAndSaysSo) {
  const std::string dir = rendered("verify-framemd5-size");
  const RunResult r =
      run_sdfreel("verify t.toml --manifest out/frames.framemd5 --resolution 32x18", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("another resolution"), std::string::npos) << r.err;
}

TEST(VerifyFramemd5, NeitherManifestNorFramemd5IsBadInputAndWritesNothing) {
  const std::string dir = rendered("verify-bad-reference");
  const struct {
    const char* name;
    std::string text;
    const char* says;
  } cases[] = {
      {"prose.txt", "these are not hashes\n", "expected a manifest.json"},
      {"short.framemd5", "#hash: MD5\n0, 0, 0, 1, 6912\n", "expected 6 comma-separated fields"},
      {"badmd5.framemd5", "0, 0, 0, 1, 6912, xyz\n", "is not an MD5"},
      {"huge.framemd5", "0, 0, 99999999999999999999, 1, 6912, 0123456789abcdef0123456789abcdef\n",
       "must be whole numbers"},
      {"empty.framemd5", "#format: frame checksums\n", "no frame lines"},
      {"sha.framemd5", "#hash: SHA256\n0, 0, 0, 1, 6912, 0123456789abcdef0123456789abcdef\n",
       "is not MD5"},
      {"broken.json", "{\"frames\": [", "not a valid sdfreel manifest.json"},
      {"other.json", "{\"hello\": 1}", "not a valid sdfreel manifest.json"},
  };
  for (const auto& c : cases) {
    write_file(dir + "/" + c.name, c.text);
    const RunResult r = run_sdfreel(std::string("verify t.toml --manifest ") + c.name, dir);
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << c.name << ": " << r.err;
  }
  const RunResult missing = run_sdfreel("verify t.toml --manifest nowhere.framemd5", dir);
  EXPECT_EQ(missing.status, 2) << missing.err;
  const RunResult folder = run_sdfreel("verify t.toml --manifest out", dir);
  EXPECT_EQ(folder.status, 2) << folder.err;
  for (const auto& e : fs::directory_iterator(dir + "/out"))
    EXPECT_EQ(e.path().filename().string().rfind("verify-", 0), std::string::npos) << e.path();
}

TEST(VerifyFramemd5, GoesOnPastTheFirstDifferenceAndListsThemAll) {
  const std::string dir = rendered("verify-all-differences");
  std::string bad = with_hash_changed(read_file(dir + "/out/frames.framemd5"), 0);
  bad = with_hash_changed(bad, 2);
  write_file(dir + "/bad.framemd5", bad);
  const RunResult r = run_sdfreel("verify t.toml --manifest bad.framemd5", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("frame 0 differs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frame 00001 ok"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frame 2 differs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 of 3 frames differ: 0, 2"), std::string::npos) << r.err;
  // --fail-fast: the old way, stopping at frame 0.
  const RunResult fast = run_sdfreel("verify t.toml --manifest bad.framemd5 --fail-fast", dir);
  EXPECT_EQ(fast.status, 1) << fast.err;
  EXPECT_NE(fast.err.find("frame 0 differs"), std::string::npos) << fast.err;
  EXPECT_EQ(fast.err.find("frame 2 differs"), std::string::npos) << fast.err;
}

// verify's --out is where the images of differing frames go (render's is the render folder):
// its help says so, and a differing frame's image lands there, not beside the manifest.
TEST(VerifyFramemd5, OutIsTheFolderOfTheImagesOfDifferingFrames) {
  const std::string dir = rendered("verify-out");
  write_file(dir + "/bad.framemd5", with_hash_changed(read_file(dir + "/out/frames.framemd5"), 1));
  const RunResult r = run_sdfreel("verify t.toml --manifest bad.framemd5 --out images", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_FALSE(fs::is_empty(dir + "/images")) << r.err;
  const std::string help = run_sdfreel("verify --help").out;
  const size_t at = help.find("--out");
  ASSERT_NE(at, std::string::npos) << help;
  const std::string line = help.substr(at, help.find('\n', at) - at);
  EXPECT_NE(line.find("images of frames that differ"), std::string::npos) << line;
  EXPECT_EQ(line.find("[output] dir"), std::string::npos) << line;
}

TEST(VerifyManifest, NamesEachSettingThatDiffersWithBothValues) {
  const std::string dir = rendered("verify-names-settings");
  const RunResult r =
      run_sdfreel("verify t.toml --manifest out/manifest.json --samples 3 --quality final", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("other settings"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("samples: 3 here, 1 in the manifest"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("quality: final here, draft in the manifest"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("resolution:"), std::string::npos) << r.err;
}

TEST(VerifyTolerance, HoldsFramesToTheGoldenPngsByFilamentsRule) {
  const std::string dir = rendered("verify-tolerance");
  const RunResult same =
      run_sdfreel("verify t.toml --manifest out/manifest.json --tolerance filament", dir);
  EXPECT_EQ(same.status, 0) << same.err;
  EXPECT_NE(same.err.find("verified 3 frames within tolerance"), std::string::npos) << same.err;
  // Frame 1's golden turned white: far outside the rule; the others still pass.
  ImageRGB16 white = read_png16(dir + "/out/frames/00001.png");
  std::fill(white.pixels.begin(), white.pixels.end(), uint16_t(65535));
  write_png16_atomic(dir + "/out/frames/00001.png", white);
  const RunResult bad = run_sdfreel(
      "verify t.toml --manifest out/manifest.json --tolerance filament --out diffs", dir);
  EXPECT_EQ(bad.status, 1) << bad.err;
  EXPECT_NE(bad.err.find("frame 00001 OUTSIDE tolerance"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("frame 00002 within tolerance"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("1 of 3 frames outside"), std::string::npos) << bad.err;
  EXPECT_TRUE(fs::exists(dir + "/diffs/verify-00001-diff.png"));
  EXPECT_FALSE(fs::exists(dir + "/diffs/verify-00000-diff.png"));
}

TEST(VerifyTolerance, OtherSettingsThanTheRendererStillFail) {
  const std::string dir = rendered("verify-tolerance-settings");
  const RunResult r = run_sdfreel(
      "verify t.toml --manifest out/manifest.json --tolerance filament --samples 2", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("samples: 2 here, 1 in the manifest"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sdfreel::test
