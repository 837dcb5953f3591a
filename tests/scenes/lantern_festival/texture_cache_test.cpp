// The lanterns' generated textures through the cache folder: the same bits made, stored, loaded
// and after a damaged cache file was made again.
#include "scenes/common/texture_cache.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/cache_file.h"
#include "scenes/lantern_festival/scene.h"
#include "support/scratch.h"

namespace sdfreel::lantern_festival {
namespace {

namespace fs = std::filesystem;

bool same_bits(const Texture& a, const Texture& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         a.texels.size() == b.texels.size() &&
         std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(float)) == 0;
}

void expect_same(const LanternTextures& a, const LanternTextures& b) {
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_TRUE(same_bits(a.blue_noise, b.blue_noise));
  EXPECT_TRUE(same_bits(a.paper_normal, b.paper_normal));
  EXPECT_TRUE(same_bits(a.paper_noise, b.paper_noise));
  EXPECT_TRUE(same_bits(a.sky, b.sky));
  EXPECT_TRUE(same_bits(a.sky_blurred, b.sky_blurred));
}

std::vector<fs::path> cache_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  return files;
}

TEST(LanternTextureCache, SameBitsMadeStoredLoadedAndRepaired) {
  const std::string dir = test::scratch_dir("lantern-texture-cache");
  const char* old = std::getenv("SDFREEL_CACHE_DIR");
  const std::string saved = old ? old : "";
  ::setenv("SDFREEL_CACHE_DIR", dir.c_str(), 1);
  const uint32_t seed = 12345u;
  const std::unique_ptr<LanternTextures> made = make_lantern_textures(seed);

  const std::unique_ptr<LanternTextures> first = cached_lantern_textures(seed);  // miss: stores
  expect_same(*made, *first);
  const std::vector<fs::path> files = cache_files(dir);
  ASSERT_EQ(files.size(), 1u);
  const auto size = fs::file_size(files[0]);

  expect_same(*made, *cached_lantern_textures(seed));  // hit

  // A truncated file (a disk that filled up under another tool) is made again and rewritten.
  fs::resize_file(files[0], size / 2);
  expect_same(*made, *cached_lantern_textures(seed));
  EXPECT_EQ(fs::file_size(files[0]), size);
  // So is a file with one changed texel.
  {
    std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(size - 1000));
    f.put('\x7f');
  }
  expect_same(*made, *cached_lantern_textures(seed));
  expect_same(*made, *cached_lantern_textures(seed));  // and the rewritten file loads

  // Another seed is another file.
  EXPECT_FALSE(same_bits(cached_lantern_textures(seed + 1)->sky, made->sky));
  EXPECT_EQ(cache_files(dir).size(), 2u);
  old ? ::setenv("SDFREEL_CACHE_DIR", saved.c_str(), 1) : ::unsetenv("SDFREEL_CACHE_DIR");
}

TEST(TextureSerialization, RefusesMalformedBytes) {
  Texture t(3, 2, 2);
  for (size_t i = 0; i < t.texels.size(); ++i) t.texels[i] = float(i) * 0.25f;
  const std::vector<char> bytes = serialize_textures({t, t});
  auto back = deserialize_textures(bytes);
  ASSERT_TRUE(back);
  ASSERT_EQ(back->size(), 2u);
  EXPECT_TRUE(same_bits((*back)[1], t));
  EXPECT_FALSE(deserialize_textures(std::vector<char>(bytes.begin(), bytes.end() - 1)));
  std::vector<char> longer = bytes;
  longer.push_back(0);
  EXPECT_FALSE(deserialize_textures(longer));
  std::vector<char> bad_size = bytes;
  bad_size[4] = char(0xff);  // width of the first texture: negative
  bad_size[7] = char(0xff);
  EXPECT_FALSE(deserialize_textures(bad_size));
}

}  // namespace
}  // namespace sdfreel::lantern_festival
