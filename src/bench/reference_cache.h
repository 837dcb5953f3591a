#pragma once
// Reference renders of the bench, on disk under DIR/reference/<key>/: per frame the display image
// (16-bit PNG, exact) and the hit mask (8-bit PNG of hit ids). The key hashes the timeline's hash
// with every reference setting and the resolution, so a reference is rendered once per timeline
// and reused by later runs; a change of scene code needs --fresh-reference (or deleting DIR).
#include <string>

#include "render/image.h"

namespace sdfreel::bench {

// SHA-256 (hex) of the text that identifies a reference: timeline hash, settings, size.
std::string reference_key(const std::string& timeline_hash, const std::string& settings, int width,
                          int height);

class ReferenceCache {
 public:
  ReferenceCache(std::string dir, std::string key);
  const std::string& folder() const { return folder_; }
  // False when the frame is not cached (or unreadable, or of another size).
  bool load(int frame, int width, int height, ImageRGB16& display, ImageRGBA& mask) const;
  // Throws std::runtime_error when the files cannot be written.
  void store(int frame, const ImageRGB16& display, const ImageRGBA& mask) const;

 private:
  std::string folder_;
};

}  // namespace sdfreel::bench
