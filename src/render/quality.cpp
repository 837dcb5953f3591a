#include "render/quality.h"

namespace sdfreel {

// The one place where preset numbers live. hit_eps and normal_eps are in units of the pixel
// footprint at unit distance: the renderer multiplies them by t * pixel_angle, so precision follows
// what a pixel can show instead of a fixed world-space epsilon.
MarchSettings march_settings(Quality q) {
  switch (q) {
    case Quality::Draft:
      return MarchSettings{96, 1.0f, 1.2f, 1.0f, 24, 48, 80.0f};
    case Quality::Final:
      return MarchSettings{256, 0.25f, 1.2f, 0.5f, 64, 128, 120.0f};
    case Quality::Reference:
      return MarchSettings{1024, 0.05f, 1.0f, 0.25f, 256, 512, 200.0f};
  }
  return march_settings(Quality::Final);
}

std::optional<Quality> parse_quality(const std::string& name) {
  if (name == "draft") return Quality::Draft;
  if (name == "final") return Quality::Final;
  if (name == "reference") return Quality::Reference;
  return std::nullopt;
}

const char* quality_name(Quality q) {
  switch (q) {
    case Quality::Draft:
      return "draft";
    case Quality::Final:
      return "final";
    case Quality::Reference:
      return "reference";
  }
  return "final";
}

}  // namespace sdfreel
