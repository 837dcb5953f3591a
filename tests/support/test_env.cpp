// Linked into every test binary, run before any test: the temporary folder and the texture cache
// are this build's own, also when a test binary runs outside ctest.
// - TMPDIR becomes <TMPDIR or /tmp>/sdfreel-tests-<hash of this build's folder>: tests use fixed
//   scratch names (sdfreel-test-NAME), which two builds testing at once (two clones, the build
//   matrix) would otherwise share and delete under each other.
// - Generated textures go to a scratch cache folder, never to the user's ~/.cache (ctest sets
//   build/test-cache).
#include <stdlib.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace {

uint64_t fnv1a(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

[[maybe_unused]] const bool kTestEnvironment = [] {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path();
  if (base.filename().string().rfind("sdfreel-tests-", 0) != 0) {  // not already ours (children)
    const fs::path own =
        base / ("sdfreel-tests-" + std::to_string(fnv1a(SDFREEL_BINARY) % 100000000));
    fs::create_directories(own);
    ::setenv("TMPDIR", own.c_str(), /*overwrite=*/1);
  }
  const std::string cache = (fs::temp_directory_path() / "sdfreel-test-cache").string();
  return ::setenv("SDFREEL_CACHE_DIR", cache.c_str(), /*overwrite=*/0) == 0;
}();

}  // namespace
