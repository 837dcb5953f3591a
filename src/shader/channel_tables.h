#pragma once
// [channels.PASS] tables: what each pass's iChannel0..3 read. The same tables sit in a timeline or
// in channels.toml beside the tabs (docs/shaders.md):
//   [channels.image]
//   iChannel0 = "buffer_a"                       # a pass: buffer_a..buffer_d, cube_a, or "self"
//   iChannel1 = { texture = "noise.png", filter = "nearest", wrap = "clamp", vflip = false }
//   iChannel2 = { cubemap = "sky.hdr" }          # one cross or equirect image, or six faces
//   iChannel3 = "none"
#include <toml++/toml.h>

#include <string>

#include "shader/shader_project.h"
#include "timeline/toml_reader.h"

namespace sdfreel {

// Binds the channels the tables name (others keep their binding). Relative file names are taken
// from `base_dir`. Throws InputError at the offending key.
void apply_channel_tables(const TomlReader& r, const toml::table& channels,
                          const std::string& base_dir, ShaderProject& project);

}  // namespace sdfreel
