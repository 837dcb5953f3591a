#pragma once
// The timeline's side of a user's shader: [video] shader = PATH read with the [shader] settings
// and the [channels] bindings (docs/shaders.md), as the ShaderLoader the parser calls.
//   [shader]
//   output = "display"        # or "linear": then the [color] view applies
//   textures = ["media"]      # where a Shadertoy JSON's texture files are looked for
//   date = [2026, 0, 1, 0]    # iDate at TIME 0 (year, month 0-11, day, seconds)
//   sample_rate = 44100       # iSampleRate
//   non_finite = "black"      # or "error": a NaN or infinite pixel fails the frame
#include "timeline/shader_loader.h"

namespace sdfreel {

struct ShaderTimelineLoader : ShaderLoader {
  std::shared_ptr<const SceneInfo> load(const TomlReader& r, const toml::table& root,
                                        const std::string& path,
                                        const std::string& name) const override;
};

}  // namespace sdfreel
