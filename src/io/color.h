#pragma once
// Scene-linear -> display transform (the shipped views in sdfreel's own math, io/shipped_views.h;
// any other config and view through OpenColorIO), and quantisation to 16-bit.
#include <memory>
#include <string>
#include <vector>

#include "render/image.h"

namespace sdfreel {

// Path of the shipped config (ocio/config.ocio), found beside the executable's source tree or
// installed data; "builtin" in a timeline means this file.
std::string builtin_ocio_config_path();

class DisplayTransform {
 public:
  // config: "builtin", or a path to a config.ocio. Throws std::runtime_error with a clear message
  // when the config, display or view does not exist.
  DisplayTransform(const std::string& config, const std::string& display, const std::string& view);
  ~DisplayTransform();
  // Linear RGBA (scene-linear Rec.709) -> display RGB, clamped to [0,1], rounded to 16 bits.
  ImageRGB16 apply(const ImageRGBA& linear) const;
  std::string description() const;  // "config / display / view" for the manifest

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Lists displays and their views of a config ("builtin" allowed), for error messages.
std::vector<std::string> ocio_displays(const std::string& config);
std::vector<std::string> ocio_views(const std::string& config, const std::string& display);

}  // namespace sdfreel
