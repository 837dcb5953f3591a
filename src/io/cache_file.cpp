#include "io/cache_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>

#include "io/atomic_file.h"
#include "io/build_id.h"
#include "io/cache_dir.h"
#include "io/fault_injection.h"

namespace sdfreel {

namespace {

constexpr char kMagic[8] = {'S', 'D', 'F', 'C', 'A', 'C', 'H', '1'};
// Cache files hold generated textures (27 MB for the lanterns); anything much larger is not ours.
constexpr uint64_t kMaxFileBytes = uint64_t(1) << 30;

std::string full_key(const std::string& key) {
  return key + "\nbuild=" + build_id();
}

uint64_t mix(uint64_t h) {
  h ^= h >> 32;
  h *= 0xd6e8feb86659fd93ull;
  h ^= h >> 32;
  return h;
}

// Reads exactly `size` bytes at `offset`.
bool read_at(int fd, void* data, size_t size, uint64_t offset) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::pread(fd, p, size, off_t(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= size_t(n);
    offset += uint64_t(n);
  }
  return true;
}

// The header written before the payload: magic, key length, key, payload length.
std::vector<char> header_of(const std::string& full_key, uint64_t payload_size) {
  const uint64_t key_size = full_key.size();
  std::vector<char> h(sizeof kMagic + 8 + key_size + 8);
  char* p = h.data();
  std::memcpy(p, kMagic, sizeof kMagic);
  std::memcpy(p + sizeof kMagic, &key_size, 8);
  std::memcpy(p + sizeof kMagic + 8, full_key.data(), key_size);
  std::memcpy(p + sizeof kMagic + 8 + key_size, &payload_size, 8);
  return h;
}

// The payload of the file at `path` if its header is exactly the one expected for `key` and
// the checksum after the payload matches. The payload is read straight into its own buffer.
std::optional<std::vector<char>> read_verified(const std::filesystem::path& path,
                                               const std::string& key) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::optional<std::vector<char>> result;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && uint64_t(st.st_size) <= kMaxFileBytes) {
    const uint64_t size = uint64_t(st.st_size);
    const size_t fixed = sizeof kMagic + 8 + key.size() + 8;
    if (size >= fixed + 8) {
      const std::vector<char> expected = header_of(key, size - fixed - 8);
      std::vector<char> header(fixed);
      std::vector<char> payload(size - fixed - 8);
      uint64_t sum = 0;
      if (read_at(fd, header.data(), fixed, 0) && header == expected &&
          read_at(fd, payload.data(), payload.size(), fixed) &&
          read_at(fd, &sum, sizeof sum, size - 8) &&
          sum == checksum64(payload.data(), payload.size()))
        result = std::move(payload);
    }
  }
  ::close(fd);
  return result;
}

// Files of one content key start with the same name, whatever the build: a new build replaces
// the files of older ones instead of piling up (27 MB each for the lanterns).
std::string content_prefix(const std::string& key) {
  char prefix[24];
  std::snprintf(prefix, sizeof prefix, "%016llx",
                static_cast<unsigned long long>(checksum64(key.data(), key.size())));
  return prefix;
}

// Removes the files of `path`'s content key written by other builds.
void remove_other_builds(const std::filesystem::path& path) {
  const std::string mine = path.filename().string();
  const std::string prefix = mine.substr(0, mine.find('-') + 1);
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(path.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name != mine && name.rfind(prefix, 0) == 0 && name.size() == mine.size())
      std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace

uint64_t checksum64(const void* data, size_t size) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  uint64_t lane[4] = {0x9e3779b97f4a7c15ull, 0xbf58476d1ce4e5b9ull, 0x94d049bb133111ebull,
                      0x2545f4914f6cdd1dull};
  size_t i = 0;
  for (; i + 32 <= size; i += 32)
    for (int k = 0; k < 4; ++k) {
      uint64_t w;
      std::memcpy(&w, p + i + 8 * k, 8);
      lane[k] = (lane[k] ^ w) * 0xff51afd7ed558ccdull;
      lane[k] ^= lane[k] >> 29;
    }
  uint64_t h = mix(lane[0]) ^ mix(lane[1] + 1) ^ mix(lane[2] + 2) ^ mix(lane[3] + 3);
  for (; i < size; ++i) h = mix(h ^ p[i]);
  return mix(h ^ uint64_t(size));
}

std::filesystem::path cache_file_path(const std::string& kind, const std::string& key) {
  const std::filesystem::path dir = cache_dir();
  if (dir.empty()) return {};
  const std::string& build = build_id();
  char name[48];
  std::snprintf(name, sizeof name, "%s-%016llx.bin", content_prefix(key).c_str(),
                static_cast<unsigned long long>(checksum64(build.data(), build.size())));
  return dir / kind / name;
}

std::optional<std::vector<char>> read_cache_file(const std::string& kind, const std::string& key) {
  const std::filesystem::path path = cache_file_path(kind, key);
  if (path.empty()) return std::nullopt;
  return read_verified(path, full_key(key));
}

bool write_cache_file(const std::string& kind, const std::string& key,
                      const std::vector<char>& payload) {
  const std::filesystem::path path = cache_file_path(kind, key);
  if (path.empty()) return false;
  const std::string k = full_key(key);
  std::vector<char> bytes = header_of(k, payload.size());
  const size_t at = bytes.size();
  const uint64_t sum = checksum64(payload.data(), payload.size());
  bytes.resize(at + payload.size() + sizeof sum);
  std::memcpy(bytes.data() + at, payload.data(), payload.size());
  std::memcpy(bytes.data() + at + payload.size(), &sum, sizeof sum);
  try {
    // Not an output of the render: the fault-injection tests count output files only.
    const FaultInjectionPause pause;
    std::filesystem::create_directories(path.parent_path());
    write_file_atomic(path.string(), bytes.data(), bytes.size());
    remove_other_builds(path);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace sdfreel
