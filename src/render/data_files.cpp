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

}  // namespace

std::vector<fs::path> data_file_candidates(const std::string& relative) {
  std::vector<fs::path> candidates;
  std::error_code ec;
  const fs::path exe_dir = fs::canonical("/proc/self/exe", ec).parent_path();
  if (ec) return candidates;
  candidates.push_back(exe_dir / ".." / "share" / "sdfreel" / relative);
#if defined(SDFREEL_SOURCE_DIR) && defined(SDFREEL_BUILD_DIR)
  const fs::path build = fs::canonical(SDFREEL_BUILD_DIR, ec);
  if (!ec && is_within(exe_dir, build))
    candidates.push_back(fs::path(SDFREEL_SOURCE_DIR) / relative);
#endif
  return candidates;
}

}  // namespace sdfreel
