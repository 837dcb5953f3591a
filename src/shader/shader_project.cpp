#include "shader/shader_project.h"

namespace sdfreel {

const char* pass_name(PassKind kind) {
  static const char* names[kPassKinds] = {"buffer_a", "buffer_b", "buffer_c",
                                          "buffer_d", "cube_a",   "image"};
  return names[int(kind)];
}

ChannelBinding default_binding(ChannelKind kind) {
  ChannelBinding b;
  b.kind = kind;
  if (kind == ChannelKind::Texture) {
    b.filter = Filter::Mipmap;
    b.wrap = Wrap::Repeat;
    b.vflip = true;
  } else if (kind == ChannelKind::Cubemap) {
    b.filter = Filter::Mipmap;
  }
  return b;
}

const ShaderPass* ShaderProject::find(PassKind kind) const {
  for (const ShaderPass& p : passes)
    if (p.kind == kind) return &p;
  return nullptr;
}

bool ShaderProject::has_feedback() const {
  for (const ShaderPass& p : passes)
    for (const ChannelBinding& c : p.channels)
      if (c.kind == ChannelKind::Pass && int(c.pass) >= int(p.kind)) return true;
  return false;
}

}  // namespace sdfreel
