#pragma once
// A manifest named on the command line (`verify --manifest FILE`, `encode DIR`) is input: when it
// is missing, not a regular file (FIFO, device), larger than the cap or malformed, that is bad
// input (UsageError, exit 2), never a hang, an unbounded read or exit 1.
#include <string>

#include "io/manifest.h"

namespace sdfreel {

Manifest read_manifest_argument(const std::string& path);

}  // namespace sdfreel
