// What sdfreel reads from a user's GLSL without compiling it: the entry point and the uniforms
// that become timeline parameters, with comments skipped and lines counted as the file has them.
#include "shader/glsl_text.h"

#include <gtest/gtest.h>

namespace sdfreel {
namespace {

TEST(GlslText, CommentsBecomeSpacesAndKeepTheirNewlines) {
  const std::string s = "a // b\nc /* d\ne */ f";
  const std::string out = without_comments(s);
  EXPECT_EQ(out.size(), s.size());
  EXPECT_EQ(out, "a     \nc     \n     f");
}

TEST(GlslText, FindsMainImageButNotInAComment) {
  EXPECT_TRUE(declares_function("void  mainImage (out vec4 c, in vec2 p) {}", "mainImage"));
  EXPECT_FALSE(declares_function("// void mainImage(out vec4 c, in vec2 p) {}", "mainImage"));
  EXPECT_FALSE(declares_function("/* void mainImage( */ void main() {}", "mainImage"));
  EXPECT_FALSE(declares_function("void mainImages(out vec4 c) {}", "mainImage"));
}

TEST(GlslText, UniformsWithTheirComponentsInitialisersAndLines) {
  const std::string s =
      "// uniform float commented;\n"
      "uniform float speed = 2.5;\n"
      "uniform highp vec3 tint = vec3(0.5);\n"
      "uniform vec2 centre = vec2(1.0, -2e1);\n"
      "uniform vec4 glow;\n"
      "uniform sampler2D not_a_param;\n";
  const std::vector<DeclaredUniform> u = declared_uniforms(s);
  ASSERT_EQ(u.size(), 4u);
  EXPECT_EQ(u[0].name, "speed");
  EXPECT_EQ(u[0].components, 1);
  EXPECT_EQ(u[0].init, std::vector<double>({2.5}));
  EXPECT_EQ(u[0].line, 2);
  EXPECT_EQ(u[1].name, "tint");
  EXPECT_EQ(u[1].init, std::vector<double>({0.5, 0.5, 0.5}));  // vec3(x) fills every component
  EXPECT_EQ(u[2].init, std::vector<double>({1.0, -20.0}));
  EXPECT_EQ(u[3].name, "glow");
  EXPECT_EQ(u[3].components, 4);
  EXPECT_TRUE(u[3].init.empty());
  EXPECT_EQ(u[3].line, 5);
}

}  // namespace
}  // namespace sdfreel
