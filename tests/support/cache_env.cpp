// Linked into every test binary: generated textures go to a scratch cache folder, never to the
// user's ~/.cache, also when a test binary runs outside ctest (which sets build/test-cache).
#include <stdlib.h>

#include <filesystem>
#include <string>

namespace {

[[maybe_unused]] const bool kScratchCache = [] {
  const std::string dir = (std::filesystem::temp_directory_path() / "sdfreel-test-cache").string();
  return ::setenv("SDFREEL_CACHE_DIR", dir.c_str(), /*overwrite=*/0) == 0;
}();

}  // namespace
