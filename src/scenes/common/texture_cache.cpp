#include "scenes/common/texture_cache.h"

#include <cstdint>
#include <cstring>

#include "io/cache_file.h"

namespace sdfreel {

namespace {

constexpr const char* kKind = "textures";
constexpr int32_t kMaxSide = 1 << 15;

void put_i32(std::vector<char>& out, int32_t v) {
  const char* p = reinterpret_cast<const char*>(&v);
  out.insert(out.end(), p, p + sizeof v);
}

}  // namespace

std::vector<char> serialize_textures(const std::vector<Texture>& textures) {
  size_t floats = 0;
  for (const Texture& t : textures) floats += t.texels.size();
  std::vector<char> out;
  out.reserve(4 + 12 * textures.size() + floats * sizeof(float));
  put_i32(out, int32_t(textures.size()));
  for (const Texture& t : textures) {
    put_i32(out, t.width);
    put_i32(out, t.height);
    put_i32(out, t.channels);
    const char* p = reinterpret_cast<const char*>(t.texels.data());
    out.insert(out.end(), p, p + t.texels.size() * sizeof(float));
  }
  return out;
}

std::optional<std::vector<Texture>> deserialize_textures(const std::vector<char>& bytes) {
  size_t at = 0;
  auto get = [&](int32_t& v) {
    if (bytes.size() - at < sizeof v) return false;
    std::memcpy(&v, bytes.data() + at, sizeof v);
    at += sizeof v;
    return true;
  };
  int32_t count = 0;
  if (!get(count) || count < 0 || count > 64) return std::nullopt;
  std::vector<Texture> textures;
  for (int32_t i = 0; i < count; ++i) {
    int32_t w = 0, h = 0, c = 0;
    if (!get(w) || !get(h) || !get(c) || w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide ||
        c <= 0 || c > 4)
      return std::nullopt;
    Texture t(w, h, c);
    const size_t size = t.texels.size() * sizeof(float);
    if (bytes.size() - at < size) return std::nullopt;
    std::memcpy(t.texels.data(), bytes.data() + at, size);
    at += size;
    textures.push_back(std::move(t));
  }
  if (at != bytes.size()) return std::nullopt;
  return textures;
}

std::vector<Texture> cached_textures(const std::string& key,
                                     const std::function<std::vector<Texture>()>& make) {
  if (auto bytes = read_cache_file(kKind, key))
    if (auto textures = deserialize_textures(*bytes)) return std::move(*textures);
  std::vector<Texture> made = make();
  write_cache_file(kKind, key, serialize_textures(made));
  return made;
}

}  // namespace sdfreel
