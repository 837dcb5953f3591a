#pragma once
// The hook through which the parser reads a user's shader named by `[video] shader`
// (docs/shaders.md), so that the timeline library does not link the shader reader.
#include <memory>
#include <string>

#include "timeline/toml_reader.h"

namespace sdfreel {

struct SceneInfo;

struct ShaderLoader {
  // The shader at `path` (resolved against the timeline's folder) as the scene named `name`, with
  // the timeline's [shader] and [channels] tables of `root` applied. Throws InputError.
  virtual std::shared_ptr<const SceneInfo> load(const TomlReader& r, const toml::table& root,
                                                const std::string& path,
                                                const std::string& name) const = 0;
  virtual ~ShaderLoader() = default;
};

}  // namespace sdfreel
