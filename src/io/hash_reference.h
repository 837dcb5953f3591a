#pragma once
// What `sdfreel verify` compares a re-render with: a manifest.json (settings, linear and display
// hashes) or an FFmpeg framemd5 (display hashes only), told apart by content, not by name.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/manifest.h"

namespace sdfreel {

struct ReferenceFrame {
  std::string display_md5;  // MD5 of the rgb48le display pixels
  std::string linear_hash;  // "" when the file does not hold it (framemd5)
  int64_t size = -1;        // bytes hashed per frame, when the file says (framemd5)
};

struct HashReference {
  std::string kind;                      // "manifest.json" or "framemd5"
  std::optional<ManifestHeader> header;  // a manifest's settings
  std::map<int, ReferenceFrame> frames;  // by frame index (a framemd5's pts)
};

// Bad input: missing, unreadable, not a regular file, too large, or neither format.
struct HashReferenceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

HashReference read_hash_reference(const std::string& path);

}  // namespace sdfreel
