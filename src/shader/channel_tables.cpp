#include "shader/channel_tables.h"

#include <filesystem>

#include "timeline/suggest.h"

namespace sdfreel {
namespace {

std::vector<std::string> pass_names() {
  std::vector<std::string> names;
  for (int k = 0; k < kPassKinds; ++k) names.push_back(pass_name(PassKind(k)));
  return names;
}

PassKind pass_named(const TomlReader& r, const toml::node& n, const std::string& key,
                    PassKind self) {
  std::vector<std::string> choices = pass_names();
  choices.push_back("self");
  const std::string name = r.choice(n, key, choices);
  if (name == "self") return self;
  for (int k = 0; k < kPassKinds; ++k)
    if (name == pass_name(PassKind(k))) return PassKind(k);
  return self;  // unreachable: choice() refused other names
}

std::string resolved(const std::string& base_dir, const std::string& file) {
  namespace fs = std::filesystem;
  return fs::path(file).is_absolute() ? file
                                      : (fs::path(base_dir) / file).lexically_normal().string();
}

ChannelBinding read_binding(const TomlReader& r, const toml::node& n, const std::string& key,
                            const std::string& base_dir, PassKind self) {
  if (const auto* s = n.as_string(); s && s->get() == "none") return {};
  if (n.is_string()) {
    ChannelBinding b = default_binding(ChannelKind::Pass);
    b.pass = pass_named(r, n, key, self);
    return b;
  }
  const toml::table& t = r.table(n, key);
  r.check_keys(t, key, {"pass", "texture", "cubemap", "filter", "wrap", "vflip", "srgb"});
  const int sources =
      int(t.contains("pass")) + int(t.contains("texture")) + int(t.contains("cubemap"));
  if (sources != 1)
    r.fail(n, key + " needs exactly one of pass, texture or cubemap (or the string \"none\")");
  ChannelBinding b;
  if (const toml::node* p = t.get("pass")) {
    b = default_binding(ChannelKind::Pass);
    b.pass = pass_named(r, *p, key + ".pass", self);
  } else if (const toml::node* tex = t.get("texture")) {
    b = default_binding(ChannelKind::Texture);
    b.files = {resolved(base_dir, r.string(*tex, key + ".texture"))};
  } else {
    const toml::node& c = *t.get("cubemap");
    b = default_binding(ChannelKind::Cubemap);
    if (c.is_array()) {
      const toml::array& faces = r.array(c, key + ".cubemap");
      if (faces.size() != 6)
        r.fail(c, key +
                      ".cubemap takes one image (a cross or an equirect) or six faces in the "
                      "order +x, -x, +y, -y, +z, -z, not " +
                      std::to_string(faces.size()));
      for (const toml::node& f : faces)
        b.files.push_back(resolved(base_dir, r.string(f, key + ".cubemap")));
    } else {
      b.files = {resolved(base_dir, r.string(c, key + ".cubemap"))};
    }
  }
  if (const toml::node* f = t.get("filter")) {
    const std::string v = r.choice(*f, key + ".filter", {"nearest", "linear", "mipmap"});
    b.filter = v == "nearest" ? Filter::Nearest : v == "linear" ? Filter::Linear : Filter::Mipmap;
  }
  if (const toml::node* w = t.get("wrap"))
    b.wrap =
        r.choice(*w, key + ".wrap", {"clamp", "repeat"}) == "clamp" ? Wrap::Clamp : Wrap::Repeat;
  if (const toml::node* v = t.get("vflip")) {
    if (!v->is_boolean()) r.fail(*v, key + ".vflip must be true or false, not " + type_name(*v));
    b.vflip = v->as_boolean()->get();
  }
  if (const toml::node* v = t.get("srgb")) {
    if (!v->is_boolean()) r.fail(*v, key + ".srgb must be true or false, not " + type_name(*v));
    if (b.kind == ChannelKind::Pass)
      r.fail(*v, key + ".srgb applies to an image file (texture or cubemap), not to a pass");
    b.srgb = v->as_boolean()->get();
  }
  return b;
}

}  // namespace

void apply_channel_tables(const TomlReader& r, const toml::table& channels,
                          const std::string& base_dir, ShaderProject& project) {
  r.check_keys(channels, "[channels]", pass_names());
  for (const auto& [key, node] : keys_in_file_order(channels)) {
    const std::string name(key->str());
    const std::string where = "channels." + name;
    ShaderPass* pass = nullptr;
    for (ShaderPass& p : project.passes)
      if (name == pass_name(p.kind)) pass = &p;
    if (!pass) {
      std::vector<std::string> have;
      for (const ShaderPass& p : project.passes) have.push_back(pass_name(p.kind));
      r.fail(*node, "[" + where + "]: this shader has no " + name + " pass (it has " +
                        join(have, " and ") + ")");
    }
    const toml::table& t = r.table(*node, where);
    r.check_keys(t, "[" + where + "]", {"iChannel0", "iChannel1", "iChannel2", "iChannel3"});
    for (const auto& [ckey, cnode] : keys_in_file_order(t)) {
      const std::string cname(ckey->str());
      ChannelBinding b = read_binding(r, *cnode, where + "." + cname, base_dir, pass->kind);
      const toml::source_position at = cnode->source().begin;
      b.origin_file = r.file();
      b.origin_line = int(at.line);
      b.origin_column = int(at.column);
      pass->channels[size_t(cname.back() - '0')] = b;
    }
  }
}

}  // namespace sdfreel
