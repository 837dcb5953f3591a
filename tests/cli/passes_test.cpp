// [output] passes end to end: the EXR frames (and a still's EXR) carry the passes as float
// channels that add up to the manifest's figures, the manifest names them, the hashes are those of
// the frames without passes, and --resume keeps such frames.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/harness.h"
#include "io/exr_file.h"

namespace sdfreel::test {
namespace {

std::string with_passes(const std::string& passes) {
  std::string t = small_timeline(3, "h264", "");
  const std::string frames = "frames = [\"exr\", \"png\"]\n";
  return t.replace(t.find(frames), frames.size(), frames + passes);
}

TEST(Passes, EveryExrFrameCarriesThemAndTheHashesStay) {
  const std::string dir = scratch_dir("passes");
  write_file(dir + "/t.toml", with_passes("passes = [\"samples\", \"sdf_evals\", \"id\"]\n"));
  RunResult r = run_sdfreel("render t.toml --no-video", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m["frame_options"]["passes"], "samples,sdf_evals,id");
  for (int i = 0; i < 3; ++i) {
    const std::string path = dir + "/out/frames/0000" + std::to_string(i) + ".exr";
    {
      Imf::InputFile file(path.c_str());
      const Imf::ChannelList& channels = file.header().channels();
      EXPECT_EQ(channels.findChannel("R")->type, Imf::HALF);
      ASSERT_NE(channels.findChannel("samples"), nullptr);
      EXPECT_EQ(channels.findChannel("samples")->type, Imf::FLOAT);
      ASSERT_NE(channels.findChannel("sdf_evals"), nullptr);
      EXPECT_EQ(channels.findChannel("sdf_evals")->type, Imf::FLOAT);
    }
    for (float v : read_exr_channel(path, "samples")) ASSERT_EQ(v, 1.0f);  // samples = 1
    int object = 0;  // sdf_morph's ids: 1 the object, 2 its pedestal, 0 anything else
    for (float v : read_exr_channel(path, "id")) {
      ASSERT_TRUE(v == 0.0f || v == 1.0f || v == 2.0f) << v;
      object += v == 1.0f;
    }
    EXPECT_GT(object, 20);
    double evals = 0.0;
    for (float v : read_exr_channel(path, "sdf_evals")) evals += v;
    const double per_pixel = m["frames"][i]["sdf_evals_per_pixel"];
    EXPECT_GT(evals, 64 * 36);
    EXPECT_NEAR(evals, per_pixel * 64 * 36, 1e-6 * evals) << "frame " << i;
  }
  write_file(dir + "/plain.toml", with_passes(""));
  ASSERT_EQ(run_sdfreel("render plain.toml --no-video --out plain", dir).status, 0);
  EXPECT_EQ(read_file(dir + "/plain/frames.framemd5"), read_file(dir + "/out/frames.framemd5"));

  r = run_sdfreel("render t.toml --no-video --resume", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("0 rendered, 3 kept from before"), std::string::npos) << r.err;

  r = run_sdfreel("still t.toml --time 0.1 -o still.exr", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_exr_channel(dir + "/still.exr", "sdf_evals"),
            read_exr_channel(dir + "/out/frames/00001.exr", "sdf_evals"));
}

}  // namespace
}  // namespace sdfreel::test
