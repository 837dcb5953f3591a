// shaders/common (det_math, noise, sdf) against their C++ twins in src/sdf, bit for bit: the
// GLSL port must compute the same floats on llvmpipe, or the two backends cannot agree.
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include "gl/gl_fixture.h"
#include "sdf/noise.h"
#include "sdf/sdf.h"

namespace sdfreel {
namespace {

using test::GlTest;

constexpr int W = 64, H = 64;  // inputs per function

// Deterministic inputs: special values first, then uniform numbers in [lo, hi).
std::vector<glm::vec4> inputs(float lo, float hi, std::vector<glm::vec4> special = {}) {
  std::vector<glm::vec4> v = std::move(special);
  uint32_t s = 12345u;
  auto next = [&] {
    s = s * 1664525u + 1013904223u;
    return lo + (hi - lo) * float(s >> 8) * (1.0f / 16777216.0f);
  };
  while (v.size() < size_t(W) * H) v.push_back(glm::vec4(next(), next(), next(), next()));
  return v;
}

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

class DetMathGlsl : public GlTest {
 protected:
  // Runs det_probe.glsl's function `f` on the inputs and compares with `cpu` component-wise.
  void compare(int f, const std::vector<glm::vec4>& in,
               const std::function<glm::vec4(const glm::vec4&)>& cpu, int components) {
    if (program < 0) program = driver->compile({"common/fullscreen.vert", "det_probe.glsl", ""});
    ShaderTexture tex{"u_inputs", W, H, 4, {}};
    for (const glm::vec4& a : in) tex.texels.insert(tex.texels.end(), {a.x, a.y, a.z, a.w});
    GlPass pass;
    pass.name = "probe";
    pass.program = program;
    pass.target = platform->frame_target(W, H);
    pass.uniforms = {{"u_function", 1, {float(f)}}};
    pass.textures = {{"u_inputs", driver->upload_texture(tex)}};
    driver->run(pass);
    const ImageRGBA img = driver->read_rgba(pass.target);
    int mismatches = 0;
    for (int i = 0; i < W * H; ++i) {
      const glm::vec4 want = cpu(in[size_t(i)]);
      const float* got = img.at(i % W, i / W);
      for (int c = 0; c < components; ++c)
        if (!same_bits(got[c], want[c]) && mismatches++ < 5)
          ADD_FAILURE() << "function " << f << " component " << c << " at input ("
                        << in[size_t(i)].x << ", " << in[size_t(i)].y << ", " << in[size_t(i)].z
                        << ", " << in[size_t(i)].w << "): GLSL " << got[c] << ", C++ " << want[c];
    }
    EXPECT_EQ(mismatches, 0) << "function " << f;
  }
  GlProgramId program = -1;
};

TEST_F(DetMathGlsl, SinCos) {
  compare(
      0,
      inputs(-1e4f, 1e4f,
             {glm::vec4(0.0f), glm::vec4(-0.0f), glm::vec4(dm::PI), glm::vec4(1e5f),
              glm::vec4(0.785f)}),
      [](const glm::vec4& a) { return glm::vec4(dm::sin(a.x), dm::cos(a.x), 0, 0); }, 2);
  compare(
      0, inputs(-7.0f, 7.0f),
      [](const glm::vec4& a) { return glm::vec4(dm::sin(a.x), dm::cos(a.x), 0, 0); }, 2);
}

TEST_F(DetMathGlsl, AtanAsinAcos) {
  compare(
      1,
      inputs(-5.0f, 5.0f,
             {glm::vec4(0.0f), glm::vec4(0.0f, -1.0f, 0, 0), glm::vec4(1.0f, 0.0f, 0, 0),
              glm::vec4(-3.0f, 3.0f, 0, 0)}),
      [](const glm::vec4& a) { return glm::vec4(dm::atan2(a.x, a.y), dm::atan(a.x), 0, 0); }, 2);
  compare(
      2, inputs(-1.2f, 1.2f, {glm::vec4(1.0f), glm::vec4(-1.0f), glm::vec4(0.5f)}),
      [](const glm::vec4& a) { return glm::vec4(dm::asin(a.x), dm::acos(a.x), 0, 0); }, 2);
}

TEST_F(DetMathGlsl, ExpTanhLogPow) {
  compare(
      3, inputs(-90.0f, 90.0f, {glm::vec4(0.0f), glm::vec4(88.7f), glm::vec4(-87.3f)}),
      [](const glm::vec4& a) { return glm::vec4(dm::exp(a.x), dm::tanh(a.x), 0, 0); }, 2);
  compare(
      3, inputs(-2.0f, 2.0f),
      [](const glm::vec4& a) { return glm::vec4(dm::exp(a.x), dm::tanh(a.x), 0, 0); }, 2);
  // Normal (not denormal) inputs: GPUs, llvmpipe included, may flush denormals to zero.
  compare(
      4,
      inputs(
          1e-3f, 50.0f,
          {glm::vec4(0.0f, 2.0f, 0, 0), glm::vec4(-1.0f, 0.5f, 0, 0), glm::vec4(1.0f, -3.0f, 0, 0),
           glm::vec4(1e-30f, 0.5f, 0, 0), glm::vec4(3e38f, 0.1f, 0, 0)}),
      [](const glm::vec4& a) { return glm::vec4(dm::log(a.x), dm::pow(a.x, a.y * 0.1f), 0, 0); },
      1);
}

TEST_F(DetMathGlsl, Noise) {
  compare(
      5, inputs(-50.0f, 50.0f),
      [](const glm::vec4& a) {
        return glm::vec4(value_noise(glm::vec3(a), 7u), value_noise(glm::vec2(a), 3u),
                         fbm(glm::vec3(a), 5, 11u), fbm(glm::vec2(a), 4, 2u));
      },
      4);
  compare(
      6, inputs(-20.0f, 20.0f),
      [](const glm::vec4& a) {
        return glm::vec4(worley(glm::vec3(a), 5u), worley(glm::vec2(a), 9u));
      },
      4);
  compare(
      10, inputs(-1e6f, 1e6f),
      [](const glm::vec4& a) {
        const glm::uvec3 h =
            pcg3d(glm::uvec3(dm::float_bits(a.x), dm::float_bits(a.y), dm::float_bits(a.z)));
        return glm::vec4(float(pcg_hash(dm::float_bits(a.x)) >> 8u), float(h.x >> 8u),
                         float(h.y >> 8u), float(h.z >> 8u));
      },
      4);
}

TEST_F(DetMathGlsl, SdfPrimitivesAndOperators) {
  compare(
      7, inputs(-2.0f, 2.0f),
      [](const glm::vec4& a) {
        const glm::vec3 p(a);
        return glm::vec4(sdTorus(p, glm::vec2(1.0f, 0.25f)), sdBox(p, glm::vec3(0.5f, 0.3f, 0.2f)),
                         sdCappedTorus(p, glm::vec2(0.8f, 0.6f), 0.7f, 0.1f),
                         sdCappedCylinder(p, 0.4f, 0.3f));
      },
      4);
  compare(
      8,
      inputs(-1.0f, 1.0f, {glm::vec4(0.3f, 0.2f, 0.0f, 0.0f), glm::vec4(0.3f, 0.2f, -1.0f, 0.0f)}),
      [](const glm::vec4& a) {
        return glm::vec4(opSmoothUnion(a.x, a.y, a.z), opSmoothSubtraction(a.x, a.y, a.z),
                         opSmoothIntersection(a.x, a.y, a.z),
                         sdRoundBox(glm::vec3(a), glm::vec3(0.4f), 0.1f));
      },
      4);
  compare(
      9, inputs(-3.0f, 3.0f, {glm::vec4(0.0f), glm::vec4(1e-20f, 0.0f, 0.0f, 0.7f)}),
      [](const glm::vec4& a) {
        return glm::vec4(safe_normalize(glm::vec3(a)), dm::smoothstep(-0.5f, 0.7f, a.w));
      },
      4);
}

}  // namespace
}  // namespace sdfreel
