#include "render/cache_dir.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

namespace sdfreel {
namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

constexpr uint64_t FNV_OFFSET = 0xcbf29ce484222325ull;
constexpr uint64_t FNV_PRIME = 0x100000001b3ull;

// FNV-1a on 64-bit words (fast enough for a 30 MB executable in a few milliseconds), then the
// tail bytes one by one.
uint64_t hash_bytes(const std::vector<char>& bytes) {
  uint64_t h = FNV_OFFSET;
  const size_t words = bytes.size() / 8;
  for (size_t i = 0; i < words; ++i) {
    uint64_t w;
    std::memcpy(&w, bytes.data() + i * 8, 8);
    h = (h ^ w) * FNV_PRIME;
  }
  for (size_t i = words * 8; i < bytes.size(); ++i) h = (h ^ uint8_t(bytes[i])) * FNV_PRIME;
  return h ^ bytes.size();
}

uint64_t hash_executable() {
  std::ifstream f("/proc/self/exe", std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.empty()) return 0;  // no /proc: the key still names scene, camera and size
  return hash_bytes(bytes);
}

}  // namespace

std::string cache_dir() {
  const std::string own = env("SDFREEL_CACHE_DIR");
  if (!own.empty()) return own;
  const std::string xdg = env("XDG_CACHE_HOME");
  if (!xdg.empty()) return xdg + "/sdfreel";
  const std::string home = env("HOME");
  if (!home.empty()) return home + "/.cache/sdfreel";
  return "";
}

uint64_t build_id() {
  static const uint64_t id = hash_executable();
  return id;
}

uint64_t content_key(const std::string& text) {
  uint64_t h = FNV_OFFSET;
  for (char c : text) h = (h ^ uint8_t(c)) * FNV_PRIME;
  return h;
}

}  // namespace sdfreel
