#include "shader/shadertoy_json.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "timeline/timeline.h"

namespace sdfreel {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct JsonReader {
  std::string path;
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path, 0, 0, what); }
  std::string text(const json& j, const char* key, const char* alt = nullptr) const {
    const json* v = j.contains(key) ? &j[key] : (alt && j.contains(alt)) ? &j[alt] : nullptr;
    if (!v || !v->is_string())
      fail(std::string("a render pass or input has no string '") + key + "'");
    return v->get<std::string>();
  }
};

// A pass's tab by its name ("Buf A", "Buffer A", "Cube A", "Image") and type.
PassKind kind_of(const JsonReader& r, const json& pass) {
  const std::string type = r.text(pass, "type");
  if (type == "image") return PassKind::Image;
  if (type == "cubemap") return PassKind::CubeA;
  if (type != "buffer")
    r.fail("render pass of type '" + type + "' is not supported (docs/shaders.md)");
  const std::string name = pass.value("name", std::string());
  if (!name.empty()) {
    const char letter = name.back();
    if (letter >= 'A' && letter <= 'D') return PassKind(int(PassKind::BufferA) + (letter - 'A'));
  }
  r.fail("buffer pass named '" + name + "': expected Buffer A .. Buffer D");
}

// Output ids name the buffer an input reads: strings ("4dXGR8") or numbers (257) by export.
std::string id_string(const json& id) {
  return id.is_string() ? id.get<std::string>() : id.dump();
}

std::string find_texture(const JsonReader& r, const std::string& src,
                         const std::vector<std::string>& dirs) {
  const std::string name = fs::path(src).filename().string();
  std::vector<std::string> tried = {fs::path(r.path).parent_path().string()};
  tried.insert(tried.end(), dirs.begin(), dirs.end());
  for (const std::string& d : tried) {
    const fs::path p = fs::path(d.empty() ? "." : d) / name;
    if (fs::is_regular_file(p)) return p.lexically_normal().string();
  }
  r.fail("texture " + src + ": no file " + name +
         " beside the JSON or in [shader] textures; download it there");
}

ChannelBinding read_input(const JsonReader& r, const json& in,
                          const std::map<std::string, PassKind>& outputs,
                          const std::vector<std::string>& dirs) {
  const std::string type = r.text(in, "ctype", "type");
  ChannelBinding b;
  if (type == "buffer") {
    b = default_binding(ChannelKind::Pass);
    const auto it = in.contains("id") ? outputs.find(id_string(in["id"])) : outputs.end();
    if (it == outputs.end()) r.fail("an input reads a buffer that no render pass writes");
    b.pass = it->second;
  } else if (type == "texture") {
    b = default_binding(ChannelKind::Texture);
    b.files = {find_texture(r, r.text(in, "src", "filepath"), dirs)};
  } else if (const auto it = in.contains("id") ? outputs.find(id_string(in["id"])) : outputs.end();
             type == "cubemap" && it != outputs.end()) {
    b = default_binding(ChannelKind::Pass);  // Cube A's output
    b.pass = it->second;
  } else if (type == "cubemap") {
    // The site's six faces: NAME.EXT for +x, then NAME_1.EXT .. NAME_5.EXT.
    b = default_binding(ChannelKind::Cubemap);
    const fs::path src = r.text(in, "src", "filepath");
    const std::string stem = (src.parent_path() / src.stem()).string();
    const std::string ext = src.extension().string();
    b.files = {find_texture(r, src.string(), dirs)};
    for (int f = 1; f < 6; ++f)
      b.files.push_back(find_texture(r, stem + "_" + std::to_string(f) + ext, dirs));
  } else {
    r.fail("input of type '" + type +
           "' is not supported (textures, cubemaps and buffers are; docs/shaders.md)");
  }
  if (const auto s = in.find("sampler"); s != in.end() && s->is_object()) {
    const std::string filter = s->value("filter", "");
    if (filter == "nearest") b.filter = Filter::Nearest;
    if (filter == "linear") b.filter = Filter::Linear;
    if (filter == "mipmap") b.filter = Filter::Mipmap;
    const std::string wrap = s->value("wrap", "");
    if (wrap == "clamp") b.wrap = Wrap::Clamp;
    if (wrap == "repeat") b.wrap = Wrap::Repeat;
    if (s->contains("vflip")) b.vflip = (*s)["vflip"] == "true" || (*s)["vflip"] == true;
    // The site writes "true"/"false" strings; a hand-written export may use booleans.
    if (s->contains("srgb") && b.kind != ChannelKind::Pass)
      b.srgb = (*s)["srgb"] == "true" || (*s)["srgb"] == true;
  }
  b.origin_file = r.path;
  return b;
}

ShaderProject read_renderpasses(const JsonReader& r, const json& passes,
                                const std::vector<std::string>& dirs) {
  if (!passes.is_array()) r.fail("'renderpass' is not a list");
  ShaderProject p;
  p.path = r.path;
  std::map<std::string, PassKind> outputs;
  for (const json& pass : passes) {
    const std::string type = r.text(pass, "type");
    if (type == "sound") r.fail("the Sound tab is not supported (docs/shaders.md lists what is)");
    if (type == "common") continue;
    const PassKind kind = kind_of(r, pass);
    if (const auto o = pass.find("outputs"); o != pass.end() && o->is_array())
      for (const json& out : *o)
        if (out.contains("id")) outputs[id_string(out["id"])] = kind;
  }
  for (const json& pass : passes) {
    if (r.text(pass, "type") == "common") {
      p.common_file = r.path + " (Common)";
      p.common_source = r.text(pass, "code");
      continue;
    }
    ShaderPass s;
    s.kind = kind_of(r, pass);
    s.file = r.path + " (" + pass_name(s.kind) + ")";
    s.source = r.text(pass, "code");
    if (p.find(s.kind)) r.fail(std::string("two render passes are ") + pass_name(s.kind));
    if (const auto in = pass.find("inputs"); in != pass.end() && in->is_array())
      for (const json& input : *in) {
        const int channel = input.value("channel", -1);
        if (channel < 0 || channel > 3) r.fail("an input's channel is not 0..3");
        try {
          s.channels[size_t(channel)] = read_input(r, input, outputs, dirs);
        } catch (const InputError& e) {  // name the pass and channel the input is bound to
          r.fail(std::string(pass_name(s.kind)) + " iChannel" + std::to_string(channel) + ": " +
                 e.what());
        }
      }
    p.passes.push_back(std::move(s));
  }
  std::sort(p.passes.begin(), p.passes.end(),
            [](const ShaderPass& a, const ShaderPass& b) { return a.kind < b.kind; });
  if (!p.find(PassKind::Image)) r.fail("no Image render pass");
  return p;
}

}  // namespace

ShaderProject read_shadertoy_json(const std::string& path, const std::string& text,
                                  const std::vector<std::string>& texture_dirs) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    int line = 1, column = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i, ++column)
      if (text[i] == '\n') ++line, column = 0;
    throw InputError(path, line, column, std::string("not valid JSON: ") + e.what());
  } catch (const json::exception& e) {  // a number too large for a double, say
    throw InputError(path, 0, 0, std::string("not valid JSON: ") + e.what());
  }
  const JsonReader r{path};
  if (j.is_array()) {  // the site's export: a list of shaders
    if (j.size() != 1) r.fail("the JSON holds " + std::to_string(j.size()) + " shaders: keep one");
    j = j[0];
  }
  if (j.is_object() && j.contains("Shader")) j = j["Shader"];  // the public API's wrapping
  if (!j.is_object() || !j.contains("renderpass"))
    r.fail("not a Shadertoy export: expected {\"Shader\": {\"renderpass\": [...]}}");
  try {
    return read_renderpasses(r, j["renderpass"], texture_dirs);
  } catch (const json::exception& e) {  // a field of another type than Shadertoy writes
    r.fail(std::string("not a Shadertoy export as sdfreel reads it: ") + e.what());
  }
}

}  // namespace sdfreel
