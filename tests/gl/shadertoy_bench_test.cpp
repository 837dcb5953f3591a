// `sdfreel bench` on a user's shader (docs/shaders.md): the configurations are the Image pass's
// samples a pixel, measured against the same shader at many samples on GL; more samples give
// less error on a picture with hard edges, and the CSV holds every row.
#include <gtest/gtest.h>

#include <sstream>

#include "gl/gl_cli_fixture.h"

namespace sdfreel {
namespace {

using test::run_sdfreel;

class ShadertoyBench : public test::GlCliTest {};

TEST_F(ShadertoyBench, SampleCountsAgainstAManySampleReference) {
  // Hard-edged rings: one sample a pixel aliases, more samples approach the reference.
  test::write_file(dir + "/rings.glsl",
                   "void mainImage(out vec4 c, in vec2 p) {\n"
                   "  float r = length(p - 0.5 * iResolution.xy);\n"
                   "  c = vec4(vec3(step(0.5, fract(r * 0.37 + iTime))), 1.0);\n}\n");
  test::write_file(dir + "/t.toml",
                   "[video]\nshader = \"rings.glsl\"\nfps = 10\nduration = 1.0\n"
                   "resolution = [64, 36]\n");
  const test::RunResult r =
      run_sdfreel("bench t.toml --frames 0 --repetitions 1 --resolution 48x32 --out bench", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("reference frame 0 (reference, 64 samples)"), std::string::npos) << r.err;
  std::istringstream csv(test::read_file(dir + "/bench/bench.csv"));
  std::string line;
  std::getline(csv, line);  // header
  std::vector<std::string> presets;
  std::vector<double> psnr;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
    ASSERT_GE(f.size(), 9u) << line;
    EXPECT_EQ(f[1], "gl") << "a shader's rows are GL's, the default cpu replaced";
    presets.push_back(f[2]);
    psnr.push_back(std::stod(f[4]));
    EXPECT_EQ(f[8], "nan") << "no hit mask for a shader";
  }
  EXPECT_EQ(presets, std::vector<std::string>({"spp=1", "spp=2", "spp=4", "spp=8", "spp=16"}));
  ASSERT_EQ(psnr.size(), 5u);
  EXPECT_LT(psnr[0] + 3.0, psnr[4]) << "16 samples should be clearly nearer the reference";
  EXPECT_EQ(r.out.find("preset targets"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sdfreel
