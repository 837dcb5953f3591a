#pragma once
// Which renders are writing into a folder right now: each holds a shared flock() on
// DIR/.render.lock for its lifetime (released by the kernel even on kill -9). A render with other
// settings uses it to refuse to replace the manifest of a live render instead of silently dropping
// that render's frames.
#include <string>

namespace sdfreel {

class FolderClaim {
 public:
  FolderClaim() = default;
  ~FolderClaim();
  FolderClaim(const FolderClaim&) = delete;
  FolderClaim& operator=(const FolderClaim&) = delete;

  // True when another process holds a claim on `dir`. Call before acquire() (a process's own
  // claim would count).
  static bool others_active(const std::string& dir);
  void acquire(const std::string& dir);  // throws std::runtime_error

 private:
  int fd_ = -1;
};

}  // namespace sdfreel
