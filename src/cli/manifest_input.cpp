#include "cli/manifest_input.h"

#include "pipeline/errors.h"

namespace sdfreel {

Manifest read_manifest_argument(const std::string& path) {
  std::optional<Manifest> m;
  try {
    m = read_manifest(path);
  } catch (const std::exception& e) {
    throw UsageError(path + ": " + e.what());
  }
  if (!m) throw UsageError("cannot read manifest " + path + ": no such file");
  return *m;
}

}  // namespace sdfreel
