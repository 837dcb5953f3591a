// Atomic publication of files: temporary file + fsync + rename.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace sdfreel {
namespace {

std::atomic<unsigned long> g_temp_counter{0};

void fsync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  // Some file systems cannot fsync a directory (EINVAL): the rename is still atomic there.
  if (rc != 0 && err != EINVAL)
    throw std::runtime_error("cannot flush " + path + " to disk: " + std::strerror(err));
}

}  // namespace

std::string temp_path_for(const std::string& path) {
  const fs::path p(path);
  const std::string name = "." + p.filename().string() + ".tmp-" + std::to_string(::getpid()) +
                           "-" + std::to_string(g_temp_counter.fetch_add(1));
  return (p.parent_path() / name).string();
}

void commit_temp_file(const std::string& temp, const std::string& path) {
  try {
    fsync_path(temp, O_RDONLY);
    if (std::rename(temp.c_str(), path.c_str()) != 0)
      throw std::runtime_error("cannot rename " + temp + " to " + path + ": " +
                               std::strerror(errno));
  } catch (...) {
    discard_temp_file(temp);
    throw;
  }
  // Make the rename itself durable.
  const fs::path dir = fs::path(path).parent_path();
  fsync_path(dir.empty() ? "." : dir.string(), O_RDONLY | O_DIRECTORY);
}

void discard_temp_file(const std::string& temp) noexcept {
  std::error_code ec;
  fs::remove(temp, ec);
}

int remove_stale_temp_files(const std::string& dir) {
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const size_t at = name.rfind(".tmp-");
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    const long pid = std::atol(name.c_str() + at + 5);
    if (pid > 0 && std::filesystem::exists("/proc/" + std::to_string(pid))) continue;
    if (std::filesystem::remove(entry.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace sdfreel
