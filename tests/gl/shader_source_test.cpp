// The #include resolver and the compiler-log mapping, without a GL context.
#include "backends/gl/shader_source.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

class ShaderSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = (fs::temp_directory_path() / ("sdfreel-shader-source-" + std::to_string(::getpid())))
              .string();
    fs::remove_all(dir);
    fs::create_directories(dir + "/lib");
  }
  void TearDown() override { fs::remove_all(dir); }
  void write(const std::string& rel, const std::string& text) {
    std::ofstream(dir + "/" + rel) << text;
  }
  std::string dir;
};

TEST_F(ShaderSourceTest, InlinesIncludesOnceWithLineDirectives) {
  write("lib/a.glsl", "float a() { return 1.0; }\n");
  write("lib/b.glsl", "#include \"lib/a.glsl\"\nfloat b() { return a(); }\n");
  write(
      "main.glsl",
      "// top\n#include \"lib/a.glsl\"\n  # include \"lib/b.glsl\"  // twice a\nvoid main() {}\n");
  const ShaderSource s = load_shader_source(dir, "main.glsl", "#version 450 core\n");
  ASSERT_EQ(s.files, (std::vector<std::string>{"main.glsl", "lib/a.glsl", "lib/b.glsl"}));
  EXPECT_EQ(s.text,
            "#version 450 core\n"
            "#line 1 0\n// top\n"
            "#line 100001 1\nfloat a() { return 1.0; }\n"
            "#line 3 0\n"
            "#line 200001 2\n"
            "#line 200002 2\nfloat b() { return a(); }\n"  // a.glsl is not included twice
            "#line 4 0\nvoid main() {}\n");
}

TEST_F(ShaderSourceTest, MissingIncludeNamesTheIncludingLine) {
  write("main.glsl", "void f();\n#include \"lib/nope.glsl\"\n");
  try {
    load_shader_source(dir, "main.glsl", "");
    FAIL() << "expected ShaderError";
  } catch (const ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("main.glsl:2: cannot read shader"), std::string::npos)
        << e.what();
  }
}

TEST_F(ShaderSourceTest, RejectsVersionAndMalformedIncludes) {
  write("v.glsl", "\n#version 450\n");
  write("m.glsl", "#include <lib/a.glsl>\n");
  EXPECT_THROW(load_shader_source(dir, "v.glsl", ""), ShaderError);
  EXPECT_THROW(load_shader_source(dir, "m.glsl", ""), ShaderError);
  EXPECT_THROW(load_shader_source(dir, "absent.glsl", ""), ShaderError);
}

TEST(ShaderLog, MapsSourceNumbersToFiles) {
  ShaderSource s;
  s.files = {"scene.glsl", "common/sdf.glsl"};
  // The file comes from the line number (Mesa sometimes reports source 0 for an included file).
  const std::string log =
      "1:100012(5): error: syntax\n0:100007(3): error: `q' undeclared\n0:3(1): warning: unused\n"
      "linker says hi\n7:700001(1): error: x\n";
  EXPECT_EQ(map_shader_log(log, s, "shaders"),
            "shaders/common/sdf.glsl:12:5: error: syntax\n"
            "shaders/common/sdf.glsl:7:3: error: `q' undeclared\n"
            "shaders/scene.glsl:3:1: warning: unused\n"
            "linker says hi\n"
            "7:700001(1): error: x\n");  // an unknown file is left as it is
}

}  // namespace
}  // namespace sdfreel
