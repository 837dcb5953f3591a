// The cache folder and its verified files: a damaged file reads as missing, never as data.
#include "io/cache_file.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>

#include "io/build_id.h"
#include "io/cache_dir.h"
#include "support/scratch.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for one test and restores it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    value ? ::setenv(name, value, 1) : ::unsetenv(name);
  }
  ~ScopedEnv() { had_ ? ::setenv(name_, old_.c_str(), 1) : ::unsetenv(name_); }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

std::vector<char> bytes_of(const std::string& s) {
  return std::vector<char>(s.begin(), s.end());
}

void overwrite(const fs::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
}

std::vector<char> read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

TEST(CacheDir, PrefersSdfreelThenXdgThenHome) {
  ScopedEnv a("SDFREEL_CACHE_DIR", "/scratch/a"), x("XDG_CACHE_HOME", "/xdg"), h("HOME", "/home/u");
  EXPECT_EQ(cache_dir(), fs::path("/scratch/a"));
  {
    ScopedEnv none("SDFREEL_CACHE_DIR", nullptr);
    EXPECT_EQ(cache_dir(), fs::path("/xdg/sdfreel"));
    ScopedEnv relative("XDG_CACHE_HOME", "relative/dir");  // invalid by the XDG spec: ignored
    EXPECT_EQ(cache_dir(), fs::path("/home/u/.cache/sdfreel"));
    ScopedEnv no_home("HOME", nullptr);
    EXPECT_TRUE(cache_dir().empty());
  }
}

TEST(BuildId, NamesThisBuild) {
  EXPECT_FALSE(build_id().empty());
  EXPECT_EQ(build_id(), build_id());
}

TEST(CacheFile, RoundTripsUnderItsKeyOnly) {
  ScopedEnv dir("SDFREEL_CACHE_DIR", test::scratch_dir("cache-roundtrip").c_str());
  const std::vector<char> payload = bytes_of("generated texels \0 and more");
  EXPECT_FALSE(read_cache_file("textures", "k1"));
  ASSERT_TRUE(write_cache_file("textures", "k1", payload));
  EXPECT_EQ(read_cache_file("textures", "k1"), payload);
  EXPECT_FALSE(read_cache_file("textures", "k2"));
  EXPECT_FALSE(read_cache_file("other", "k1"));
  // Nothing but the file itself is left (no temporaries).
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(cache_dir())) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(CacheFile, ANewBuildReplacesTheFilesOfOlderBuildsOfItsKey) {
  ScopedEnv dir("SDFREEL_CACHE_DIR", test::scratch_dir("cache-builds").c_str());
  const fs::path mine = cache_file_path("textures", "k");
  const std::string name = mine.filename().string();
  const fs::path older = mine.parent_path() / (name.substr(0, name.find('-')) +
                                               "-0123456789abcdef.bin");  // another build's
  ASSERT_TRUE(write_cache_file("textures", "other key", bytes_of("x")));
  const fs::path other_key = cache_file_path("textures", "other key");
  overwrite(older, bytes_of("an older build's textures"));
  ASSERT_TRUE(fs::exists(older));
  ASSERT_TRUE(write_cache_file("textures", "k", bytes_of("y")));
  EXPECT_FALSE(fs::exists(older));
  EXPECT_TRUE(fs::exists(mine));
  EXPECT_TRUE(fs::exists(other_key));
}

TEST(CacheFile, DamagedFilesReadAsMissing) {
  ScopedEnv dir("SDFREEL_CACHE_DIR", test::scratch_dir("cache-damaged").c_str());
  std::vector<char> payload(100000);
  for (size_t i = 0; i < payload.size(); ++i) payload[i] = char(i * 7919 >> 3);
  ASSERT_TRUE(write_cache_file("textures", "k", payload));
  const fs::path path = cache_file_path("textures", "k");
  const std::vector<char> good = read_all(path);

  for (size_t cut : {size_t(0), size_t(5), good.size() / 2, good.size() - 1}) {
    overwrite(path, std::vector<char>(good.begin(), good.begin() + std::ptrdiff_t(cut)));
    EXPECT_FALSE(read_cache_file("textures", "k")) << "truncated to " << cut;
  }
  for (size_t at : {size_t(3), size_t(40), good.size() / 2, good.size() - 3}) {
    std::vector<char> bad = good;
    bad[at] ^= 0x10;
    overwrite(path, bad);
    EXPECT_FALSE(read_cache_file("textures", "k")) << "bit flipped at " << at;
  }
  std::vector<char> longer = good;
  longer.push_back(0);
  overwrite(path, longer);
  EXPECT_FALSE(read_cache_file("textures", "k"));
  overwrite(path, good);
  EXPECT_EQ(read_cache_file("textures", "k"), payload);
}

TEST(CacheFile, AnUnwritableFolderOnlyMeansNoCache) {
  const std::string scratch = test::scratch_dir("cache-unwritable");
  test::write_file(scratch + "/file", "not a folder");
  ScopedEnv dir("SDFREEL_CACHE_DIR", (scratch + "/file").c_str());
  EXPECT_FALSE(write_cache_file("textures", "k", bytes_of("x")));
  EXPECT_FALSE(read_cache_file("textures", "k"));
}

TEST(Checksum64, SeesEveryByteAndTheLength) {
  std::vector<char> a(1000, 'a');
  const uint64_t base = checksum64(a.data(), a.size());
  EXPECT_NE(checksum64(a.data(), a.size() - 1), base);
  for (size_t i : {size_t(0), size_t(31), size_t(32), size_t(999)}) {
    std::vector<char> b = a;
    b[i] = 'b';
    EXPECT_NE(checksum64(b.data(), b.size()), base) << i;
  }
}

}  // namespace
}  // namespace sdfreel
