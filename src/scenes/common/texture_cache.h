#pragma once
// Generated textures are pure functions of their parameters, and some take a second to make
// (lantern_festival's 2048x1024 sky, void-and-cluster blue noise): keep them in the cache folder
// (io/cache_file.h) by content key. A missing, damaged or other-build file is made again; the
// texels are the same bits either way.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scenes/common/texture.h"

namespace sdfreel {

// `key` names everything the textures depend on (scene, generator version, every parameter); the
// build is added by the cache. Returns the cached textures, or make()'s, which are then stored.
std::vector<Texture> cached_textures(const std::string& key,
                                     const std::function<std::vector<Texture>()>& make);

// The byte form of a texture list, and back (nothing when the bytes are not a valid list).
std::vector<char> serialize_textures(const std::vector<Texture>& textures);
std::optional<std::vector<Texture>> deserialize_textures(const std::vector<char>& bytes);

}  // namespace sdfreel
