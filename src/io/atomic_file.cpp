// Atomic publication of files: temporary file + checked writes + fsync + rename.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "io/fault_injection.h"
#include "io/temp_name.h"

namespace fs = std::filesystem;

namespace sdfreel {
namespace {

std::atomic<unsigned long> g_temp_counter{0};

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
  throw std::runtime_error("cannot " + what + " " + path + ": " + std::strerror(err));
}

// Errors name `shown`: the file being published, which is what the user knows.
void fsync_path(const std::string& path, int flags, const std::string& shown) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) fail("open", shown, errno);
  const int rc = inject_io_fault() ? -1 : ::fsync(fd);
  const int err = errno;
  ::close(fd);
  // Some file systems cannot fsync a directory (EINVAL): the rename is still atomic there.
  if (rc != 0 && err != EINVAL) fail("flush to disk", shown, err);
}

}  // namespace

std::string temp_path_for(const std::string& path) {
  const fs::path p(path);
  const std::string name = "." + p.filename().string() + ".tmp-" + temp_host_name() + "-" +
                           std::to_string(::getpid()) + "-" +
                           std::to_string(g_temp_counter.fetch_add(1));
  return (p.parent_path() / name).string();
}

int write_fully(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    if (inject_io_fault()) return ENOSPC;
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return ENOSPC;  // no progress and no error: treat as a full disk
    p += n;
    size -= size_t(n);
  }
  return 0;
}

int sync_and_close(int fd) {
  int err = 0;
  if (inject_io_fault() || ::fsync(fd) != 0) err = errno;
  // close() can report a deferred write error (NFS, some FUSE file systems): it counts too.
  if ((inject_io_fault() || ::close(fd) != 0) && err == 0) err = errno;
  return err;
}

void write_file_atomic(const std::string& path, const void* data, size_t size) {
  const std::string temp = temp_path_for(path);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) fail("write", path, errno);
  int err = write_fully(fd, data, size);
  struct stat st {};
  if (err == 0 && ::fstat(fd, &st) != 0) err = errno;
  if (err == 0 && st.st_size != off_t(size)) err = ENOSPC;  // short file: never publish
  if (err != 0) {
    ::close(fd);
  } else {
    err = sync_and_close(fd);
  }
  if (err != 0) {
    discard_temp_file(temp);
    fail("write", path, err);
  }
  commit_temp_file(temp, path);
}

void commit_temp_file(const std::string& temp, const std::string& path) {
  try {
    fsync_path(temp, O_RDONLY, path);
    if (inject_io_fault() || std::rename(temp.c_str(), path.c_str()) != 0)
      throw std::runtime_error("cannot rename " + temp + " to " + path + ": " +
                               std::strerror(errno));
  } catch (...) {
    discard_temp_file(temp);
    throw;
  }
  // Make the rename itself durable.
  const fs::path dir = fs::path(path).parent_path();
  fsync_path(dir.empty() ? "." : dir.string(), O_RDONLY | O_DIRECTORY, path + " (its folder)");
}

void discard_temp_file(const std::string& temp) noexcept {
  std::error_code ec;
  fs::remove(temp, ec);
}

int remove_stale_temp_files(const std::string& dir) {
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const TempName t = parse_temp_name(entry.path().filename().string());
    // Another node's temporaries are its own business: its PIDs mean nothing here.
    if (!t.valid || t.host != temp_host_name()) continue;
    if (fs::exists("/proc/" + std::to_string(t.pid))) continue;
    if (fs::remove(entry.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace sdfreel
