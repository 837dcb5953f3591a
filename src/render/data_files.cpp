#include "render/data_files.h"

#include <system_error>

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

// True when `dir` is `root` or inside it (both canonical).
bool is_within(const fs::path& dir, const fs::path& root) {
  auto d = dir.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++d)
    if (d == dir.end() || *d != *r) return false;
  return true;
}

fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// True when the running executable lies inside the build tree it was built in.
bool in_build_tree(const fs::path& exe_dir) {
#if defined(SDFREEL_BUILD_DIR)
  std::error_code ec;
  const fs::path build = fs::canonical(SDFREEL_BUILD_DIR, ec);
  return !ec && is_within(exe_dir, build);
#else
  (void)exe_dir;
  return false;
#endif
}

}  // namespace

std::vector<fs::path> data_file_candidates(const std::string& relative) {
  std::vector<fs::path> candidates;
  const fs::path exe_dir = executable_dir();
  if (exe_dir.empty()) return candidates;
  candidates.push_back(exe_dir / ".." / "share" / "sdfreel" / relative);
#if defined(SDFREEL_SOURCE_DIR)
  if (in_build_tree(exe_dir)) candidates.push_back(fs::path(SDFREEL_SOURCE_DIR) / relative);
#endif
  return candidates;
}

std::vector<fs::path> module_file_candidates(const std::string& name) {
  std::vector<fs::path> candidates;
  const fs::path exe_dir = executable_dir();
  if (exe_dir.empty()) return candidates;
  candidates.push_back(exe_dir / ".." / "lib" / "sdfreel" / name);
#if defined(SDFREEL_BUILD_DIR)
  if (in_build_tree(exe_dir))
    candidates.push_back(fs::path(SDFREEL_BUILD_DIR) / "lib" / "sdfreel" / name);
#endif
  return candidates;
}

}  // namespace sdfreel
