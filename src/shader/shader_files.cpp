#include "shader/shader_files.h"

#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "shader/channel_tables.h"
#include "shader/glsl_text.h"
#include "shader/shadertoy_json.h"
#include "timeline/timeline.h"
#include "timeline/toml_errors.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

constexpr uintmax_t kMaxShaderBytes = 4u << 20;

void read_channels_file(const std::string& file, ShaderProject& p) {
  const std::string text = read_shader_text(file);
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(file));
  } catch (const toml::parse_error& e) {
    throw InputError(file, int(e.source().begin.line), int(e.source().begin.column),
                     toml_error_message(std::string(e.description())));
  }
  TomlReader r(file);
  r.check_keys(root, "", {"channels"});
  if (const toml::node* c = root.get("channels"))
    apply_channel_tables(r, r.table(*c, "channels"), fs::path(file).parent_path().string(), p);
}

ShaderProject read_folder(const std::string& dir) {
  ShaderProject p;
  p.path = dir;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".glsl") continue;
    const std::string stem = entry.path().stem().string();
    bool known = stem == "common";
    for (int k = 0; k < kPassKinds; ++k) known = known || stem == pass_name(PassKind(k));
    if (stem == "sound")
      throw InputError(entry.path().string(), 0, 0,
                       "the Sound tab is not supported (docs/shaders.md lists what is); move it "
                       "out of the folder");
    if (!known)
      throw InputError(entry.path().string(), 0, 0,
                       "unknown tab '" + name +
                           "': a shader folder holds image.glsl, buffer_a.glsl .. buffer_d.glsl, "
                           "cube_a.glsl and common.glsl");
  }
  if (fs::exists(dir + "/common.glsl")) {
    p.common_file = dir + "/common.glsl";
    p.common_source = read_shader_text(p.common_file);
  }
  for (int k = 0; k < kPassKinds; ++k) {
    const std::string file = dir + "/" + pass_name(PassKind(k)) + ".glsl";
    if (!fs::exists(file)) continue;
    ShaderPass pass;
    pass.kind = PassKind(k);
    pass.file = file;
    pass.source = read_shader_text(file);
    p.passes.push_back(std::move(pass));
  }
  if (!p.find(PassKind::Image))
    throw InputError(dir, 0, 0, "no image.glsl in this folder: a shader needs its Image tab");
  if (fs::exists(dir + "/channels.toml")) read_channels_file(dir + "/channels.toml", p);
  return p;
}

}  // namespace

std::string read_shader_text(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(path, 0, 0, fs::exists(path, ec) ? "not a regular file" : "no such file");
  if (fs::file_size(path, ec) > kMaxShaderBytes)
    throw InputError(path, 0, 0, "larger than 4 MiB: not a shader");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in) throw InputError(path, 0, 0, "cannot read the file");
  return s.str();
}

std::string read_shader_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in) throw InputError(path, 0, 0, "cannot read the file");
  return s.str();
}

ShaderProject read_shader_files(const std::string& path,
                                const std::vector<std::string>& texture_dirs) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return read_folder(path);
  if (!fs::exists(path, ec)) throw InputError(path, 0, 0, "no such file or folder");
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".json") return read_shadertoy_json(path, read_shader_text(path), texture_dirs);
  if (ext != ".glsl" && ext != ".frag")
    throw InputError(path, 0, 0,
                     "a shader is a folder of tabs, a .glsl file or Shadertoy's .json export");
  ShaderProject p;
  p.path = path;
  ShaderPass image;
  image.file = path;
  image.source = read_shader_text(path);
  p.passes.push_back(std::move(image));
  return p;
}

void check_shader_project(const ShaderProject& p) {
  // The GL backend numbers each source's lines below 100000 (backends/gl/shader_source.h).
  auto check_lines = [](const std::string& file, const std::string& source) {
    if (std::count(source.begin(), source.end(), '\n') >= 99999)
      throw InputError(file, 0, 0, "more than 99999 lines: not a shader sdfreel can compile");
  };
  check_lines(p.common_file, p.common_source);
  for (const ShaderPass& pass : p.passes) {
    check_lines(pass.file, pass.source);
    const bool cube = pass.kind == PassKind::CubeA;
    const char* entry = cube ? "mainCubemap" : "mainImage";
    if (!declares_function(pass.source, entry))
      throw InputError(pass.file, 0, 0,
                       std::string("no ") + entry + " function: Shadertoy's " +
                           (cube ? "Cube A tab" : "tabs") + " define void " + entry +
                           (cube ? "(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in "
                                   "vec3 rayDir)"
                                 : "(out vec4 fragColor, in vec2 fragCoord)"));
    for (size_t c = 0; c < 4; ++c) {
      const ChannelBinding& b = pass.channels[c];
      const std::string file = b.origin_file.empty() ? pass.file : b.origin_file;
      const std::string what = std::string(pass_name(pass.kind)) + " iChannel" + std::to_string(c);
      if (b.kind == ChannelKind::Pass && b.pass == PassKind::Image)
        throw InputError(file, b.origin_line, b.origin_column,
                         what +
                             " reads the Image pass, which no channel can read (as on the site): "
                             "draw into a buffer and read that");
      if (b.kind == ChannelKind::Pass && !p.find(b.pass))
        throw InputError(file, b.origin_line, b.origin_column,
                         what + " reads " + pass_name(b.pass) +
                             ", which this shader does not have (no " + pass_name(b.pass) +
                             " tab)");
      for (const std::string& f : b.files)
        if (!fs::is_regular_file(f))
          throw InputError(file, b.origin_line, b.origin_column,
                           what + ": image file " + f + " not found");
    }
  }
}

}  // namespace sdfreel
