// A user's shader whose buffers read their own past (docs/shaders.md, "Frames that depend on
// earlier frames"): every frame has the same bits rendered in sequence, alone, in two shards, on
// resume after kill -9 and as a still, because a render that starts at frame k replays the
// buffers from frame 0 first.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "gl/gl_cli_fixture.h"
#include "io/frame_files.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using test::run_sdfreel;

// Buffer A adds a pixel- and frame-dependent amount to its own last value (wrapping at 1): frame
// k's buffer is a sum over frames 0..k, so a frame rendered without its past would differ.
// Buffer B reads A of this frame and B of the last; Image shows both. `cost` loops make a frame
// slow enough to be killed mid-render.
std::string buffer_a(int cost) {
  return "void mainImage(out vec4 c, in vec2 p) {\n"
         "  vec4 last = texelFetch(iChannel0, ivec2(p), 0);\n"
         "  float step = fract(sin(dot(p, vec2(12.9898, 78.233)) + float(iFrame)) * 43758.5453);\n"
         "  float slow = 0.0;\n"
         "  for (int i = 0; i < " +
         std::to_string(cost) +
         "; ++i) slow += sin(float(i) + p.x);\n"
         "  c = vec4(fract(last.x + 0.25 * step + 1e-9 * slow), iTime, 0.0, 1.0);\n"
         "}\n";
}
const char* kBufferB =
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  c = 0.5 * texelFetch(iChannel1, ivec2(p), 0) + 0.5 * texelFetch(iChannel0, ivec2(p), 0);\n"
    "}\n";
const char* kImage =
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  c = vec4(texture(iChannel0, p / iResolution.xy).x, shade(texture(iChannel1, p / "
    "iResolution.xy).x), 0.5, 1.0);\n"
    "}\n";
const char* kCommon = "float shade(float x) { return x * x; }\n";
const char* kChannels =
    "[channels.buffer_a]\niChannel0 = \"self\"\n\n"
    "[channels.buffer_b]\niChannel0 = \"buffer_a\"\niChannel1 = \"self\"\n\n"
    "[channels.image]\niChannel0 = { pass = \"buffer_a\", filter = \"nearest\" }\n"
    "iChannel1 = { pass = \"buffer_b\", filter = \"nearest\" }\n";

class ShadertoyFeedback : public test::GlCliTest {
 protected:
  // The shader folder and a timeline of `frames` frames at 10 fps naming it.
  void write(int frames, const std::string& resolution = "[16, 8]", int cost = 0,
             const std::string& extra = "") {
    fs::create_directories(dir + "/tabs");
    test::write_file(dir + "/tabs/buffer_a.glsl", buffer_a(cost));
    test::write_file(dir + "/tabs/buffer_b.glsl", kBufferB);
    test::write_file(dir + "/tabs/image.glsl", kImage);
    test::write_file(dir + "/tabs/common.glsl", kCommon);
    test::write_file(dir + "/tabs/channels.toml", kChannels);
    test::write_file(dir + "/t.toml",
                     "[video]\nshader = \"tabs\"\nfps = 10\nduration = " +
                         std::to_string(frames / 10.0) + "\nresolution = " + resolution +
                         "\n\n[output]\nframes = [\"png\"]\nvideo = \"\"\n" + extra);
  }
  std::vector<std::string> hashes(const std::string& out) {
    return test::framemd5_frame_lines(dir + "/" + out + "/frames.framemd5");
  }
  std::string render(const std::string& out, const std::string& args = "") {
    const test::RunResult r = run_sdfreel("render t.toml --out " + out + " " + args, dir);
    EXPECT_EQ(r.status, 0) << r.err;
    return r.err;
  }
};

TEST_F(ShadertoyFeedback, FramesAreTheSameAloneInShardsOnResumeAndInSequence) {
  write(8);
  render("sequence");
  const std::vector<std::string> all = hashes("sequence");
  ASSERT_EQ(all.size(), 8u);
  EXPECT_NE(all[6].substr(all[6].rfind(',')), all[7].substr(all[7].rfind(',')))
      << "the frames should change";

  // Alone: frame 6 replays frames 0..5 first, and says so.
  const std::string err = render("alone", "--frames 6");
  EXPECT_NE(err.find("replaying"), std::string::npos) << err;
  ASSERT_EQ(hashes("alone").size(), 1u);
  EXPECT_EQ(hashes("alone")[0], all[6]);

  // llvmpipe's thread count changes nothing either.
  const test::RunResult one =
      run_sdfreel("render t.toml --out one-thread", dir, "LP_NUM_THREADS=1 ");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(hashes("one-thread"), all);

  render("shards", "--shard 1/2");
  render("shards", "--shard 0/2");
  EXPECT_EQ(hashes("shards"), all);

  render("resumed", "--frames 0-2,5");
  render("resumed", "--resume");
  EXPECT_EQ(hashes("resumed"), all);
}

TEST_F(ShadertoyFeedback, FramesAreTheSameAfterKillAndResume) {
  write(30, "[128, 64]", 3000);
  const test::RunResult killed = test::run(
      "'" + test::sdfreel_binary() + "' render t.toml --out killed 2>/dev/null & pid=$!; " +
          "for i in $(seq 1500); do n=$(ls killed/frames 2>/dev/null | grep -c png); " +
          "[ \"$n\" -ge 3 ] && break; sleep 0.02; done; kill -9 $pid; wait $pid; echo $?",
      dir);
  ASSERT_EQ(killed.out, "137\n") << "the render was not killed mid-run";
  render("killed", "--resume");
  render("sequence");
  EXPECT_EQ(hashes("killed"), hashes("sequence"));
}

TEST_F(ShadertoyFeedback, LaterRangesAndVerifyStartFromCheckpointsWithTheSameBits) {
  write(8, "[16, 8]", 0, "\n[shader]\ncheckpoint_every = 3\n");
  render("sequence");
  const std::vector<std::string> all = hashes("sequence");
  const std::string kept = dir + "/sequence/checkpoints/";
  // Before frames 3 and 6; none before frame 0 or the end.
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(kept)) files.push_back(e.path().filename());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, std::vector<std::string>({"buffers-00003.ckpt", "buffers-00006.ckpt"}));

  // A later range (a shard, a resume) starts from the latest checkpoint at or before it.
  std::string err = render("sequence", "--frames 7");
  EXPECT_NE(err.find("from the checkpoint before frame 6"), std::string::npos) << err;
  EXPECT_NE(err.find("replaying the shader's buffers of frames 6-6 for frame 7"), std::string::npos)
      << err;
  EXPECT_EQ(hashes("sequence"), all);

  // A corrupted checkpoint is not used, with a warning: the one before it is, the frame is the
  // same, and the replay writes the damaged one again.
  std::string bytes = test::read_file(kept + "buffers-00006.ckpt");
  bytes[bytes.size() / 2] ^= 0x10;
  test::write_file(kept + "buffers-00006.ckpt", bytes);
  err = render("sequence", "--frames 7");
  EXPECT_NE(err.find("buffers-00006.ckpt is not used: a wrong checksum"), std::string::npos) << err;
  EXPECT_NE(err.find("from the checkpoint before frame 3"), std::string::npos) << err;
  EXPECT_EQ(hashes("sequence"), all);
  err = render("sequence", "--frames 7");
  EXPECT_EQ(err.find("warning"), std::string::npos) << err;
  EXPECT_NE(err.find("from the checkpoint before frame 6"), std::string::npos) << err;

  // verify reads the reference's checkpoints and writes none.
  fs::remove(kept + "buffers-00003.ckpt");
  for (const char* frame : {"7", "5"}) {
    const test::RunResult v = run_sdfreel(
        std::string("verify t.toml --manifest sequence/manifest.json --frames ") + frame, dir);
    EXPECT_EQ(v.status, 0) << v.err;
    EXPECT_EQ(v.err.find("from the checkpoint before frame 6") != std::string::npos,
              std::string(frame) == "7")
        << v.err;
  }
  EXPECT_FALSE(fs::exists(kept + "buffers-00003.ckpt"));
}

TEST_F(ShadertoyFeedback, StillAtATimeIsThatFrame) {
  write(8);
  render("sequence");
  const test::RunResult r = run_sdfreel("still t.toml --time 0.5 -o still.png", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_png16(dir + "/still.png").pixels,
            read_png16(dir + "/sequence/frames/00005.png").pixels);
}

}  // namespace
}  // namespace sdfreel
