#include "backends/gl/shadertoy_source.h"

#include <regex>

#include "backends/gl/shader_source.h"
#include "shader/shadertoy_uniforms.h"

namespace sdfreel {

namespace {

// Source string numbers of #line: 0 the wrapper, 1 Common, 2 the pass. Mesa reports 0 for some
// errors whatever #line said, so the number is also encoded in the line as in the built-in
// scenes' shaders (shader_source.h): line n of source k is k * SHADER_LINE_BLOCK + n.
constexpr int kCommonSource = 1, kPassSource = 2;

std::string line_directive(int source, int line) {
  return "#line " + std::to_string(source * SHADER_LINE_BLOCK + line) + " " +
         std::to_string(source) + "\n";
}

// A channel the pass samples as a cube: a cubemap file, or Cube A's output.
bool reads_cube(const ChannelBinding& b) {
  return b.kind == ChannelKind::Cubemap ||
         (b.kind == ChannelKind::Pass && b.pass == PassKind::CubeA);
}

// #version, Shadertoy's define and every uniform of shadertoy_uniforms() (iChannelN a samplerCube
// where the pass reads a cube, as the site declares it), then sdfreel's own.
std::string header(const ShaderPass& pass) {
  std::string s = "#version 450 core\n#define HW_PERFORMANCE 1\n";
  for (const ShadertoyUniform& u : shadertoy_uniforms()) {
    std::string type = u.type;
    const std::string name = u.name;
    if (name.size() == 9 && name.rfind("iChannel", 0) == 0 &&
        reads_cube(pass.channels[size_t(name[8] - '0')]))
      type = "samplerCube";
    s += "uniform " + type + " " + name + (u.array ? "[4];\n" : ";\n");
  }
  return s +
         "uniform vec2 sdfreel_offset;  // the sample's sub-pixel offset\nout vec4 "
         "sdfreel_color;\n";
}

const char* kMain = R"(
#line 1 0
void main() {
  vec4 color = vec4(0.0);
  mainImage(color, floor(gl_FragCoord.xy) + sdfreel_offset);
  sdfreel_color = color;
}
)";

// Cube A, as the site runs it: each face is drawn with the ray from the centre through the
// fragment, interpolated between the face's corners (shadertoy_cube.cpp).
const char* kCubeMain = R"(
#line 1 0
uniform vec3 sdfreel_corners[5];  // the face's four corners, then the rays' origin
void main() {
  vec4 color = vec4(0.0, 0.0, 0.0, 1.0);
  vec2 fragCoord = floor(gl_FragCoord.xy) + sdfreel_offset;
  vec2 uv = fragCoord / iResolution.xy;
  vec3 ro = sdfreel_corners[4];
  vec3 rd = normalize(mix(mix(sdfreel_corners[0], sdfreel_corners[1], uv.x),
                          mix(sdfreel_corners[3], sdfreel_corners[2], uv.x), uv.y) - ro);
  mainCubemap(color, fragCoord, ro, rd);
  sdfreel_color = color;
}
)";

}  // namespace

std::string shadertoy_fragment_source(const ShaderProject& project, const ShaderPass& pass) {
  std::string s = header(pass);
  if (!project.common_source.empty())
    s += line_directive(kCommonSource, 1) + project.common_source + "\n";
  s += line_directive(kPassSource, pass.first_line) + pass.source + "\n" +
       (pass.kind == PassKind::CubeA ? kCubeMain : kMain);
  return s;
}

InputError shadertoy_compile_error(const ShaderProject& project, const ShaderPass& pass,
                                   const std::string& log) {
  // Mesa writes "2:14(7): error: ...", NVIDIA "2(14) : error ...".
  static const std::regex where(R"((\d+):(\d+)\((\d+)\)|(\d+)\((\d+)\))");
  std::string first_file;
  int first_line = 0, first_column = 0;
  std::string out;
  auto file_of = [&](int source) {
    return source == kCommonSource ? project.common_file
           : source == kPassSource ? pass.file
                                   : std::string("(sdfreel's wrapper)");
  };
  std::sregex_iterator it(log.begin(), log.end(), where), end;
  size_t copied = 0;
  for (; it != end; ++it) {
    const std::smatch& m = *it;
    const bool mesa = m[1].matched;
    const int numbered = std::stoi(mesa ? m[2].str() : m[5].str());
    const int source = numbered / SHADER_LINE_BLOCK, line = numbered % SHADER_LINE_BLOCK;
    const int column = mesa ? std::stoi(m[3].str()) : 0;
    const std::string file = file_of(source);
    out += log.substr(copied, size_t(m.position(0)) - copied);
    out += file + ":" + std::to_string(line) + (column ? ":" + std::to_string(column) : "");
    copied = size_t(m.position(0) + m.length(0));
    if (first_file.empty() && source != 0) {
      first_file = file;
      first_line = line;
      first_column = column;
    }
  }
  out += log.substr(copied);
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return InputError(first_file.empty() ? pass.file : first_file, first_line, first_column,
                    std::string("the ") + pass_name(pass.kind) + " pass does not compile:\n" + out);
}

}  // namespace sdfreel
