#include "io/cache_dir.h"

#include <cstdlib>

namespace sdfreel {

namespace {

const char* non_empty_env(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? v : nullptr;
}

}  // namespace

std::filesystem::path cache_dir() {
  if (const char* dir = non_empty_env("SDFREEL_CACHE_DIR")) return dir;
  // The XDG base directory spec: relative values are invalid and to be ignored.
  if (const char* xdg = non_empty_env("XDG_CACHE_HOME"); xdg && *xdg == '/')
    return std::filesystem::path(xdg) / "sdfreel";
  if (const char* home = non_empty_env("HOME"))
    return std::filesystem::path(home) / ".cache/sdfreel";
  return {};
}

}  // namespace sdfreel
