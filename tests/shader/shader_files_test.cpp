// Reading a user's shader from disk: one .glsl file (an Image-only shader) or a folder of
// Shadertoy's tabs, and the refusals that name the file and what to fix.
#include "shader/shader_files.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/scratch.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

const char* kImage = "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n";

std::string error_of(const std::string& path) {
  try {
    check_shader_project(read_shader_files(path, {}));
  } catch (const InputError& e) {
    return e.formatted();
  }
  return "";
}

TEST(ShaderFiles, OneGlslFileIsAnImageOnlyShader) {
  const std::string dir = test::scratch_dir("shader-one-file");
  test::write_file(dir + "/mine.glsl", kImage);
  const ShaderProject p = read_shader_files(dir + "/mine.glsl", {});
  ASSERT_EQ(p.passes.size(), 1u);
  EXPECT_EQ(p.passes[0].kind, PassKind::Image);
  EXPECT_EQ(p.passes[0].source, kImage);
  EXPECT_EQ(p.passes[0].file, dir + "/mine.glsl");
  EXPECT_TRUE(p.common_source.empty());
  EXPECT_FALSE(p.has_feedback());
  EXPECT_NO_THROW(check_shader_project(p));
}

TEST(ShaderFiles, AFolderHoldsTabsInShadertoysOrderWithCommon) {
  const std::string dir = test::scratch_dir("shader-folder");
  test::write_file(dir + "/image.glsl", kImage);
  test::write_file(dir + "/buffer_b.glsl", kImage);
  test::write_file(dir + "/buffer_a.glsl", kImage);
  test::write_file(dir + "/common.glsl", "float twice(float x) { return 2.0 * x; }\n");
  const ShaderProject p = read_shader_files(dir, {});
  ASSERT_EQ(p.passes.size(), 3u);
  EXPECT_EQ(p.passes[0].kind, PassKind::BufferA);
  EXPECT_EQ(p.passes[1].kind, PassKind::BufferB);
  EXPECT_EQ(p.passes[2].kind, PassKind::Image);
  EXPECT_EQ(p.common_file, dir + "/common.glsl");
}

TEST(ShaderFiles, RefusalsNameTheFileAndWhatToFix) {
  const std::string dir = test::scratch_dir("shader-refusals");
  EXPECT_NE(error_of(dir + "/missing.glsl").find("no such file"), std::string::npos);
  test::write_file(dir + "/notes.txt", "hello");
  EXPECT_NE(error_of(dir + "/notes.txt").find("a .glsl file"), std::string::npos);
  test::write_file(dir + "/empty.glsl", "void main() {}\n");
  EXPECT_NE(error_of(dir + "/empty.glsl").find("no mainImage function"), std::string::npos);

  const std::string tabs = dir + "/tabs";
  std::filesystem::create_directories(tabs);
  EXPECT_NE(error_of(tabs).find("no image.glsl"), std::string::npos);
  test::write_file(tabs + "/image.glsl", kImage);
  test::write_file(tabs + "/buffer_e.glsl", kImage);
  EXPECT_NE(error_of(tabs).find("unknown tab 'buffer_e.glsl'"), std::string::npos);
  std::filesystem::remove(tabs + "/buffer_e.glsl");
  test::write_file(tabs + "/sound.glsl", kImage);
  EXPECT_NE(error_of(tabs).find("the Sound tab is not supported"), std::string::npos);
}

}  // namespace
}  // namespace sdfreel
