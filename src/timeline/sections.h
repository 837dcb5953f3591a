#pragma once
// The timeline parser, one function per top-level table. Each reads its table (which may be
// absent: the defaults stay) into the Timeline and throws InputError on bad input.
#include <vector>

#include "scenes/scene.h"
#include "timeline/shader_loader.h"
#include "timeline/timeline.h"
#include "timeline/toml_reader.h"

namespace sdfreel {

// [video]; returns the scene it names (required), one of `scenes`, or the user's shader it names
// read through `shaders` (kept in tl.shader_scene).
const SceneInfo& parse_video(const TomlReader& r, const toml::table& root,
                             const std::vector<SceneInfo>& scenes, const ShaderLoader* shaders,
                             Timeline& tl);
// [video] adaptive (after quality, whose preset gives the defaults).
void parse_adaptive(const TomlReader& r, const toml::table& video, Timeline& tl);
void parse_output(const TomlReader& r, const toml::table& root, const SceneInfo& scene,
                  Timeline& tl);
// [output] frames and the options of the formats OpenImageIO writes (parse_output_files.cpp).
void parse_frame_files(const TomlReader& r, const toml::table& output, Timeline& tl);
// [output] audio, audio_offset, audio_fade (parse_output_files.cpp).
void parse_soundtrack(const TomlReader& r, const toml::table& output, Timeline& tl);
// [output] passes, after frames (parse_passes.cpp).
void parse_passes(const TomlReader& r, const toml::table& output, const SceneInfo& scene,
                  Timeline& tl);
void parse_color(const TomlReader& r, const toml::table& root, Timeline& tl);
void parse_time(const TomlReader& r, const toml::table& root, Timeline& tl);
void parse_camera(const TomlReader& r, const toml::table& root, const SceneInfo& scene,
                  Timeline& tl);
void parse_params(const TomlReader& r, const toml::table& root, const SceneInfo& scene,
                  Timeline& tl);

}  // namespace sdfreel
