#include "io/folder_claim.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sdfreel {
namespace {

int open_lock(const std::string& dir) {
  const std::string path = dir + "/.render.lock";
  const int fd = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  return fd;
}

}  // namespace

FolderClaim::~FolderClaim() {
  if (fd_ >= 0) ::close(fd_);
}

bool FolderClaim::others_active(const std::string& dir) {
  const int fd = open_lock(dir);
  const bool busy = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);  // also drops the exclusive lock if we got it
  return busy;
}

void FolderClaim::acquire(const std::string& dir) {
  if (fd_ >= 0) return;
  fd_ = open_lock(dir);
  if (::flock(fd_, LOCK_SH) != 0)
    throw std::runtime_error("cannot lock " + dir + "/.render.lock: " + std::strerror(errno));
}

}  // namespace sdfreel
