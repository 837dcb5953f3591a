// Frame files beyond EXR and PNG (docs/timeline.md#frame-formats): written by OpenImageIO through
// the image module, read back here with OpenImageIO itself and compared with the PNG and EXR of
// the same frame; resume and encode check the exact ones, and an unknown extension is exit 2.
#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/frame_files.h"
#include "io/video_encoder.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// A small sdf_morph timeline (64x36, 10 fps) keeping the frame files `formats`, with more
// [output] keys. Its frames key is on line 11.
std::string timeline(int frames, const std::string& formats, const std::string& keys = "") {
  return "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = " + std::to_string(frames / 10.0) +
         "\nresolution = [64, 36]\nsamples = 1\nquality = \"draft\"\n\n[output]\ndir = \"out\"\n"
         "frames = [" +
         formats + "]\n" + keys +
         "\n[camera]\nkeys = [\n  { t = 0.0, position = [0.0, 1.5, -4.0], target = [0.0, 0.6, 0.0] "
         "},\n  { t = 2.0, position = [3.0, 1.8, -2.5], target = [0.0, 0.7, 0.0] },\n]\n";
}

struct Read {
  OIIO::ImageSpec spec;
  std::vector<float> values;  // OpenImageIO's 0..1 (integer files) or the stored floats
};

Read read(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  Read r;
  if (!in) return r;
  r.spec = in->spec();
  r.values.resize(size_t(r.spec.width) * r.spec.height * r.spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.values.data()));
  return r;
}

// Largest difference, in units of 1/65535, between a file's RGB and the frame's PNG.
double largest_difference(const Read& file, const ImageRGB16& png) {
  double worst = 0.0;
  for (size_t p = 0; p < png.pixels.size() / 3; ++p)
    for (int c = 0; c < 3; ++c)
      worst =
          std::max(worst, std::fabs(std::round(file.values[p * file.spec.nchannels + c] * 65535.0) -
                                    png.pixels[p * 3 + c]));
  return worst;
}

// Frames --resume kept, by its progress lines.
size_t kept_frames(const std::string& err) {
  size_t kept = 0;
  for (size_t at = 0; (at = err.find(" kept (frame", at)) != std::string::npos; ++at) ++kept;
  return kept;
}

TEST(FrameFormats, DisplayFormatsHoldThePngsPixelsInTheirBits) {
  const std::string dir = scratch_dir("formats-display");
  write_file(dir + "/t.toml", timeline(2, "\"png\", \"tif\", \"dpx\", \"jpg\", \"tga\""));
  const RunResult r = run_sdfreel("render t.toml --no-video", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const ImageRGB16 png = read_png16(dir + "/out/frames/00001.png");
  const Read tif = read(dir + "/out/frames/00001.tif");
  EXPECT_EQ(tif.spec.format, OIIO::TypeDesc::UINT16);
  EXPECT_EQ(tif.spec.nchannels, 3);
  EXPECT_EQ(largest_difference(tif, png), 0.0);  // 16 bits: the same values
  const Read dpx = read(dir + "/out/frames/00001.dpx");
  EXPECT_EQ(dpx.spec.get_int_attribute("oiio:BitsPerSample"), 10);
  EXPECT_LE(largest_difference(dpx, png), 65535.0 / 1023 / 2 + 1);  // rounded to 10 bits
  const Read jpg = read(dir + "/out/frames/00001.jpg");
  EXPECT_EQ(jpg.spec.format, OIIO::TypeDesc::UINT8);
  double sum = 0.0;
  for (size_t p = 0; p < png.pixels.size(); ++p)
    sum += std::fabs(jpg.values[p] * 65535.0 - png.pixels[p]);
  EXPECT_LT(sum / png.pixels.size(), 3.0 * 257) << "mean error over 3/255 at quality 95";
  const Read tga = read(dir + "/out/frames/00001.tga");  // any format OpenImageIO writes
  EXPECT_EQ(tga.spec.width, 64);
  EXPECT_LE(largest_difference(tga, png), 257.0 / 2 + 1);  // 8 bits
  // The manifest lists the files and the options that shaped them; the hashes are the PNG's.
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m["frame_files"], nlohmann::json({"png", "tif", "dpx", "jpg", "tga"}));
  EXPECT_EQ(m["frame_options"],
            nlohmann::json({{"tiff_bits", 16}, {"dpx_bits", 10}, {"jpeg_quality", 95}}));
}

TEST(FrameFormats, FloatTiffHoldsTheExrsLinearPixels) {
  const std::string dir = scratch_dir("formats-float");
  write_file(dir + "/t.toml", timeline(1, "\"exr\", \"tiff\"", "tiff_bits = 32\n"));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  const ImageRGBA exr = read_exr(dir + "/out/frames/00000.exr");
  const Read tif = read(dir + "/out/frames/00000.tiff");
  EXPECT_EQ(tif.spec.format, OIIO::TypeDesc::FLOAT);
  ASSERT_EQ(tif.values.size(), exr.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < exr.pixels.size(); ++i)
    differing += float(half(tif.values[i])) != exr.pixels[i];
  EXPECT_EQ(differing, 0u) << "the TIFF's floats round to the EXR's halves";
}

TEST(FrameFormats, ExrSettingsShapeTheFileNotTheHashes) {
  const std::string dir = scratch_dir("formats-exr");
  write_file(dir + "/t.toml", timeline(2, "\"exr\""));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  const std::string plain = read_file(dir + "/out/frames.framemd5");
  write_file(dir + "/t.toml", timeline(2, "\"exr\"", "exr_compression = \"zip\"\nexr_bits = 32\n"));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  const Read exr = read(dir + "/out/frames/00001.exr");
  EXPECT_EQ(exr.spec.format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(exr.spec.get_string_attribute("compression"), "zip");
  EXPECT_EQ(read_file(dir + "/out/frames.framemd5"), plain);
  const auto m = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  EXPECT_EQ(m["frame_options"], nlohmann::json({{"exr_bits", 32}, {"exr_compression", "zip"}}));
  RunResult r = run_sdfreel("render t.toml --no-video --resume", dir);
  EXPECT_EQ(kept_frames(r.err), 2u) << r.err;

  // DWAA is lossy: its frames only deliver.
  write_file(dir + "/t.toml", timeline(2, "\"exr\"", "exr_compression = \"dwaa\"\n"));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  r = run_sdfreel("encode out -o v.mkv --codec ffv1", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("cannot be checked against the manifest"), std::string::npos) << r.err;
}

TEST(FrameFormats, ResumeAndEncodeCheckExactFilesAndRefuseLossyOnes) {
  const std::string dir = scratch_dir("formats-resume");
  write_file(dir + "/t.toml", timeline(3, "\"tif\""));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  // A frame file that is another frame's is found and that frame rendered again.
  fs::copy_file(dir + "/out/frames/00000.tif", dir + "/out/frames/00002.tif",
                fs::copy_options::overwrite_existing);
  RunResult r = run_sdfreel("render t.toml --no-video --resume", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("00002.tif differs from the manifest"), std::string::npos) << r.err;
  EXPECT_EQ(kept_frames(r.err), 2u) << r.err;
  r = run_sdfreel("encode out -o v.mkv --codec ffv1", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("(3 frames, ffv1)"), std::string::npos) << r.err;

  const std::string lossy = scratch_dir("formats-lossy");
  write_file(lossy + "/t.toml", timeline(2, "\"jpg\""));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", lossy).status, 0);
  r = run_sdfreel("encode out -o v.mkv --codec ffv1", lossy);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("cannot be checked against the manifest"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(lossy + "/v.mkv"));
}

// An animated WebP read back with OpenImageIO: one subimage a frame, the PNG's colours (libwebp
// makes its own Y'CbCr; a wrong matrix or range would shift them by far more than its loss).
TEST(FrameFormats, AnimatedWebpHoldsEveryFrameInThePngsColours) {
  const std::string dir = scratch_dir("formats-webp");
  write_file(dir + "/t.toml", timeline(3, "\"png\""));
  const RunResult r = run_sdfreel("render t.toml --video loop.webp", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  auto in = OIIO::ImageInput::open(dir + "/out/loop.webp");
  ASSERT_TRUE(in) << OIIO::geterror();
  int subimages = 0;
  while (in->seek_subimage(subimages, 0)) ++subimages;
  EXPECT_EQ(subimages, 3);
  ASSERT_TRUE(in->seek_subimage(2, 0));
  const OIIO::ImageSpec spec = in->spec();
  std::vector<float> values(size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(2, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, values.data()));
  const ImageRGB16 png = read_png16(dir + "/out/frames/00002.png");
  ASSERT_EQ(spec.width * spec.height, png.width * png.height);
  double sum = 0.0;
  for (size_t p = 0; p < png.pixels.size() / 3; ++p)
    for (int c = 0; c < 3; ++c)
      sum += std::fabs(values[p * spec.nchannels + c] * 255.0 - png.pixels[p * 3 + c] / 257.0);
  EXPECT_LT(sum / double(png.pixels.size()), 4.0) << "mean error in 8-bit units";
}

// The primaries through the WebP encoder and OpenImageIO's reader (libwebp's decoder): the
// BT.601 matrix in tv range gives them back; BT.709's would move green by about 20/255.
TEST(FrameFormats, AnimatedWebpKeepsThePrimaries) {
  const std::string dir = scratch_dir("formats-webp-primaries");
  const uint16_t colours[3][3] = {{65535, 0, 0}, {0, 65535, 0}, {0, 0, 65535}};
  VideoSettings s;
  s.path = dir + "/p.webp";
  s.codec = "webp";
  s.width = 64;
  s.height = 36;
  s.fps = {10, 1};
  {
    VideoEncoder encoder(s);
    for (const auto& c : colours) {
      ImageRGB16 frame(64, 36);
      for (size_t i = 0; i < frame.pixels.size(); ++i) frame.pixels[i] = c[i % 3];
      encoder.add_frame(frame);
    }
    encoder.finish();
  }
  auto in = OIIO::ImageInput::open(s.path);
  ASSERT_TRUE(in) << OIIO::geterror();
  for (int f = 0; f < 3; ++f) {
    ASSERT_TRUE(in->seek_subimage(f, 0));
    const OIIO::ImageSpec spec = in->spec();
    std::vector<float> v(size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(f, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, v.data()));
    const float* centre = &v[(size_t(18) * spec.width + 32) * spec.nchannels];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(centre[c] * 255.0, colours[f][c] / 257.0, 4.0)
          << "frame " << f << " channel " << c;
  }
}

// The compositing passes as OpenImageIO (a reader of our EXRs that is not ours) sees them: the
// channels named as compositors expect, and values that make sense of sdf_morph's frame: one
// sample, ids 0 to 2, unit normals where there is a surface, none (and Z = 1e10) where there is
// not, and the floor's normal straight up.
TEST(FrameFormats, ExrPassesReadBackWithOpenImageIO) {
  const std::string dir = scratch_dir("formats-passes");
  write_file(dir + "/t.toml", timeline(1, "\"exr\"",
                                       "passes = [\"samples\", \"sdf_evals\", \"id\", \"depth\", "
                                       "\"normal\"]\n"));
  const RunResult r = run_sdfreel("render t.toml --no-video", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const Read exr = read(dir + "/out/frames/00000.exr");
  const std::vector<std::string> names = {"R",  "G", "B",   "A",   "samples", "sdf_evals",
                                          "id", "Z", "N.X", "N.Y", "N.Z"};
  std::vector<int> at;
  for (const std::string& name : names) {
    at.push_back(exr.spec.channelindex(name));
    ASSERT_GE(at.back(), 0) << "no channel " << name;
  }
  const int nc = exr.spec.nchannels;
  int floor = 0, surfaces = 0;
  for (size_t p = 0; p < size_t(exr.spec.width) * exr.spec.height; ++p) {
    auto v = [&](int k) { return exr.values[p * nc + size_t(at[size_t(k)])]; };
    ASSERT_EQ(v(4), 1.0f);  // samples = 1
    ASSERT_TRUE(v(6) == 0.0f || v(6) == 1.0f || v(6) == 2.0f) << v(6);
    const float length = std::sqrt(v(8) * v(8) + v(9) * v(9) + v(10) * v(10));
    if (v(7) == 1e10f) {
      ASSERT_EQ(length, 0.0f);
      continue;
    }
    ASSERT_NEAR(length, 1.0f, 1e-5f);
    ++surfaces;
    floor += v(6) == 0.0f && v(9) == 1.0f;
  }
  EXPECT_GT(surfaces, 64 * 36 / 3);
  EXPECT_GT(floor, 64 * 36 / 10);
}

TEST(FrameFormats, AnExtensionNoWriterTakesIsExitTwoAtItsPlace) {
  const std::string dir = scratch_dir("formats-bad");
  write_file(dir + "/t.toml", timeline(1, "\"png\", \"xyz\""));
  RunResult r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("t.toml:11:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("writes no .xyz files"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  EXPECT_EQ(run_sdfreel("check t.toml", dir).status, 2);
  for (const char* bad : {"\"TIF\"", "\".png\"", "\"\""}) {
    write_file(dir + "/t.toml", timeline(1, bad));
    r = run_sdfreel("render t.toml", dir);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("by its file extension in lower case"), std::string::npos) << r.err;
  }
  write_file(dir + "/t.toml", timeline(1, "\"tif\"", "tiff_bits = 24\n"));
  r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("output.tiff_bits = 24: use 8, 16 or 32"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(FrameFormats, StillWritesAnyFormatByItsExtension) {
  const std::string dir = scratch_dir("formats-still");
  write_file(dir + "/t.toml", timeline(4, "\"png\""));
  ASSERT_EQ(run_sdfreel("still t.toml --time 0.25 -o a.png", dir).status, 0);
  for (const char* name : {"a.tif", "a.jpg", "a.DPX"}) {
    const RunResult r = run_sdfreel(std::string("still t.toml --time 0.25 -o ") + name, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read(dir + "/" + name).spec.width, 64) << name;
  }
  EXPECT_EQ(largest_difference(read(dir + "/a.tif"), read_png16(dir + "/a.png")), 0.0);
  const RunResult bad = run_sdfreel("still t.toml --time 0.25 -o a.xyz", dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("writes no .xyz files"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir + "/a.xyz"));
  // OpenImageIO is loaded for these formats only (render_test: never for a PNG).
  const RunResult loads = run_sdfreel("still t.toml --time 0.25 -o b.tif", dir, "LD_DEBUG=files ");
  EXPECT_NE(loads.err.find("libOpenImageIO"), std::string::npos);
}

}  // namespace
}  // namespace sdfreel::test
