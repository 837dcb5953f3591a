// libFuzzer target: the [channels.PASS] tables of a shader's timeline or channels.toml, then the
// project check every load runs. Any bytes end in bindings or an InputError (exit 2), nothing
// else; accepted bindings are well formed: a texture names one file, a cubemap one or six, a pass
// binding reads a buffer or Cube A the shader has, never the Image pass.
#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "shader/channel_tables.h"
#include "shader/shader_files.h"
#include "timeline/timeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sdfreel;
  const std::string text(reinterpret_cast<const char*>(data), size);
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view("fuzz.toml"));
  } catch (const toml::parse_error&) {
    return 0;
  }
  ShaderProject p;  // every tab, each with a mainImage or mainCubemap, no files
  for (int k = 0; k < kPassKinds; ++k) {
    ShaderPass pass;
    pass.kind = PassKind(k);
    pass.file = std::string(pass_name(pass.kind)) + ".glsl";
    pass.source = pass.kind == PassKind::CubeA
                      ? "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) {}"
                      : "void mainImage(out vec4 c, in vec2 f) {}";
    p.passes.push_back(pass);
  }
  try {
    TomlReader r("fuzz.toml");
    if (const toml::node* c = root.get("channels"))
      apply_channel_tables(r, r.table(*c, "channels"), "/nonexistent", p);
    check_shader_project(p);
  } catch (const InputError&) {
    return 0;
  }
  for (const ShaderPass& pass : p.passes)
    for (const ChannelBinding& b : pass.channels) {
      if (b.kind == ChannelKind::Texture && b.files.size() != 1) std::abort();
      if (b.kind == ChannelKind::Cubemap && b.files.size() != 1 && b.files.size() != 6)
        std::abort();
      if (b.kind == ChannelKind::Pass && (b.pass == PassKind::Image || !p.find(b.pass)))
        std::abort();
    }
  return 0;
}
