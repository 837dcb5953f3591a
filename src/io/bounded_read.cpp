#include "io/bounded_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sdfreel {
namespace {

// What read_regular_file refuses in a file of this status, or "".
std::string status_problem(const struct stat& st, uint64_t max_bytes) {
  if (!S_ISREG(st.st_mode)) return "not a regular file (a FIFO, device or directory)";
  if (uint64_t(st.st_size) > max_bytes)
    return "larger than " + std::to_string(max_bytes >> 20) + " MiB";
  return "";
}

}  // namespace

void check_regular_file(const std::string& path, uint64_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  if (std::string problem = status_problem(st, max_bytes); !problem.empty())
    throw std::runtime_error("cannot read " + path + ": " + problem);
}

std::optional<std::string> read_regular_file(const std::string& path, uint64_t max_bytes) {
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of blocking.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) return std::nullopt;
    throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  }
  struct stat st {};
  std::string problem;
  if (::fstat(fd, &st) != 0)
    problem = std::strerror(errno);
  else
    problem = status_problem(st, max_bytes);
  std::string bytes;
  if (problem.empty()) {
    // Stops one byte past the cap, in case the file grows while it is read.
    char chunk[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fd, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) problem = std::strerror(errno);
      if (n <= 0) break;
      bytes.append(chunk, size_t(n));
      if (bytes.size() > max_bytes) {
        problem = "larger than " + std::to_string(max_bytes >> 20) + " MiB";
        break;
      }
    }
  }
  ::close(fd);
  if (!problem.empty()) throw std::runtime_error("cannot read " + path + ": " + problem);
  return bytes;
}

}  // namespace sdfreel
