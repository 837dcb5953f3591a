// The GL driver on OSMesa: context, float target, row order, compile errors as FILE:LINE,
// uniform checks, meshes with depth, instancing, off-screen passes and textures.
#include <string>

#include "gl/gl_fixture.h"

namespace sdfreel {
namespace {

using test::GlTest;

GlPass full_screen(GlProgramId program, const GlTargetRef& target) {
  GlPass p;
  p.name = "test";
  p.program = program;
  p.target = target;
  return p;
}

TEST_F(GlTest, CreatesAtLeastAGl45CoreContext) {
  const GlApi& gl = platform->gl();
  // "4.5 (Core Profile) Mesa 22.3.6"; Mesa 26 gives 4.6: at least 4.5, core.
  const std::string version = gl.string(GL_VERSION);
  GLint major = 0, minor = 0, profile = 0;
  gl.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl.GetIntegerv(GL_MINOR_VERSION, &minor);
  gl.GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45) << version;
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << version;
  EXPECT_FALSE(gl.string(GL_RENDERER).empty());
  const GlTargetRef t = platform->frame_target(33, 17);
  EXPECT_NE(t.framebuffer, 0u);
  EXPECT_EQ(t.width, 33);
  EXPECT_EQ(t.height, 17);
  EXPECT_EQ(platform->frame_target(33, 17).framebuffer, t.framebuffer);  // kept while the size is
}

TEST_F(GlTest, SolidShaderGivesExactFloatsTopRowFirst) {
  const GlProgramId prog = driver->compile({"common/fullscreen.vert", "solid.glsl", ""});
  const GlTargetRef t = platform->frame_target(7, 5);
  GlPass pass = full_screen(prog, t);
  // Values outside [0, 1] and not representable in 8 bits: the target must be float, unclamped.
  pass.uniforms = {{"u_colour", 4, {0.123456789f, -2.5f, 1234.5678f, 0.0f}},
                   {"u_resolution", 2, {7.0f, 5.0f}}};
  driver->run(pass);
  const ImageRGBA img = driver->read_rgba(t);
  ASSERT_EQ(img.width, 7);
  ASSERT_EQ(img.height, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) {
      const float* p = img.at(x, y);
      EXPECT_EQ(p[0], 0.123456789f);
      EXPECT_EQ(p[1], -2.5f);
      EXPECT_EQ(p[2], 1234.5678f);
      EXPECT_EQ(p[3], float(y * 1000 + x)) << "pixel " << x << "," << y;
    }
}

TEST_F(GlTest, CompileErrorNamesFileAndLineOfTheIncludedFile) {
  try {
    driver->compile({"common/fullscreen.vert", "broken.glsl", ""});
    FAIL() << "expected a ShaderError";
  } catch (const ShaderError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(test::test_shader_dir() + "/broken_lib.glsl:4:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("error"), std::string::npos) << msg;
  }
}

TEST_F(GlTest, UndeclaredNameInAnIncludedFileNamesThatFile) {
  try {
    driver->compile({"common/fullscreen.vert", "undeclared.glsl", ""});
    FAIL() << "expected a ShaderError";
  } catch (const ShaderError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(test::test_shader_dir() + "/undeclared_lib.glsl:3:"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("not_declared_anywhere"), std::string::npos) << msg;
  }
}

TEST_F(GlTest, PassThatLeavesAUniformUnsetIsRefused) {
  const GlProgramId prog = driver->compile({"common/fullscreen.vert", "unset.glsl", ""});
  GlPass pass = full_screen(prog, platform->frame_target(4, 4));
  pass.uniforms = {{"u_a", 1, {1.0f}}};
  try {
    driver->run(pass);
    FAIL() << "expected a ShaderError";
  } catch (const ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("'u_b'"), std::string::npos) << e.what();
  }
  pass.uniforms = {{"u_a", 1, {1.0f}}, {"u_b", 3, {1.0f, 2.0f, 3.0f}}};  // wrong type
  EXPECT_THROW(driver->run(pass), ShaderError);
  pass.uniforms = {{"u_a", 1, {1.0f}}, {"u_b", 1, {2.0f}}, {"u_unused", 1, {3.0f}}};
  driver->run(pass);
  EXPECT_EQ(driver->read_rgba(pass.target).at(2, 2)[1], 2.0f);
}

TEST_F(GlTest, StructArraysAndPlainArraysAreSetByName) {
  const GlProgramId prog = driver->compile({"common/fullscreen.vert", "structs.glsl", ""});
  GlPass pass = full_screen(prog, platform->frame_target(2, 2));
  pass.uniforms = {
      {"u_s.count", 1, {2.0f}},           {"u_s.items[0].colour", 3, {1.0f, 2.0f, 3.0f}},
      {"u_s.items[0].weight", 1, {0.5f}}, {"u_s.items[1].colour", 3, {10.0f, 20.0f, 30.0f}},
      {"u_s.items[1].weight", 1, {2.0f}}, {"u_list", 1, {1.0f, 2.0f, 3.0f}}};
  driver->run(pass);
  const float* p = driver->read_rgba(pass.target).at(1, 0);
  EXPECT_EQ(p[0], 20.5f);
  EXPECT_EQ(p[1], 41.0f);
  EXPECT_EQ(p[2], 61.5f);
  EXPECT_EQ(p[3], 321.0f);
  pass.uniforms.back().values.push_back(4.0f);  // longer than the array
  EXPECT_THROW(driver->run(pass), ShaderError);
}

// Two full-screen triangles: far red, then near green, then the same again in the opposite order.
TEST_F(GlTest, MeshPassDepthTestKeepsTheNearestSurface) {
  const GlProgramId prog = driver->compile({"mesh.vert", "mesh.frag", ""});
  auto triangle = [](float z, float r, float g, GlMesh& m) {
    const float xy[] = {-1, -1, 3, -1, -1, 3};
    for (int i = 0; i < 3; ++i) {
      m.positions.insert(m.positions.end(), {xy[2 * i], xy[2 * i + 1], z});
      m.normals.insert(m.normals.end(), {r, g, 0.0f});
    }
  };
  GlMesh far_first, near_first;
  triangle(0.5f, 1.0f, 0.0f, far_first);
  triangle(-0.5f, 0.0f, 1.0f, far_first);
  triangle(-0.5f, 0.0f, 1.0f, near_first);
  triangle(0.5f, 1.0f, 0.0f, near_first);
  near_first.indices = {0, 1, 2, 3, 4, 5};
  const GlTargetRef t = platform->frame_target(8, 8);
  for (GlMeshId mesh : {driver->create_mesh(far_first), driver->create_mesh(near_first)}) {
    GlPass pass = full_screen(prog, t);
    pass.mesh = mesh;
    pass.depth = DepthMode::TestAndWrite;
    driver->run(pass);
    const float* p = driver->read_rgba(t).at(3, 4);
    EXPECT_EQ(p[0], 0.0f) << "mesh " << mesh;
    EXPECT_EQ(p[1], 1.0f) << "mesh " << mesh;
  }
  GlPass no_depth = full_screen(prog, t);  // control: without the test the last triangle wins
  no_depth.mesh = 1;
  driver->run(no_depth);
  EXPECT_EQ(driver->read_rgba(t).at(3, 4)[0], 1.0f);
}

TEST_F(GlTest, InstancesWithAdditiveBlendSumOncePerInstance) {
  const GlProgramId prog = driver->compile({"common/fullscreen.vert", "instances.glsl", ""});
  GlPass pass = full_screen(prog, platform->frame_target(4, 4));
  pass.instances = 5;
  pass.blend = BlendMode::Add;
  pass.uniforms = {{"u_value", 1, {0.25f}}};
  driver->run(pass);
  const float* p = driver->read_rgba(pass.target).at(1, 1);
  EXPECT_EQ(p[0], 1.25f);
  EXPECT_EQ(p[1], 2.5f);
}

TEST_F(GlTest, TexturesAndOffscreenTargetsFeedLaterPasses) {
  const GlProgramId copy = driver->compile({"common/fullscreen.vert", "texel_copy.glsl", ""});
  ShaderTexture tex{"u_source", 3, 2, 4, {}};
  for (int i = 0; i < 3 * 2 * 4; ++i) tex.texels.push_back(0.1f * float(i) - 0.7f);
  // Pass 1: scene texture -> off-screen target (times 2). Pass 2: that target -> frame (times 3).
  const GlRenderTarget& off = driver->create_render_target(3, 2, 1, false);
  GlPass first = full_screen(copy, off.ref);
  first.textures = {{"u_source", driver->upload_texture(tex)}};
  first.uniforms = {{"u_scale", 1, {2.0f}}, {"u_flip", 1, {0.0f}}};
  driver->run(first);
  GlPass second = full_screen(copy, platform->frame_target(3, 2));
  second.textures = {{"u_source", off.color_textures[0]}};
  second.uniforms = {{"u_scale", 1, {3.0f}}, {"u_flip", 1, {1.0f}}};
  driver->run(second);
  const ImageRGBA img = driver->read_rgba(second.target);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(img.at(x, y)[c], tex.texels[size_t((y * 3 + x) * 4 + c)] * 2.0f * 3.0f)
            << x << "," << y << "," << c;
}

}  // namespace
}  // namespace sdfreel
