#pragma once
// The views of `sdfreel map`: cameras of the scene's own renderer fitted to a timeline's camera
// path, one looking down the scene's up axis and one from the side, and where a world point lands
// in each image (the same projection as primary_ray_dir, so marks sit on what was rendered).
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "render/camera.h"

namespace sdfreel::draw {

struct MapView {
  std::string name;  // "from above", "from the side"
  CameraPose pose;
  int width = 0, height = 0;
  double units_per_pixel = 0.0;  // at the path's nearest point to the camera (for a scale bar)
};

// Above the points along `up`, looking straight down, no higher than `ceiling` (where the field of
// view widens instead), `width` pixels wide and as high as the points' extent asks (0.35 to 1.0
// of the width).
MapView view_from_above(const std::vector<glm::dvec3>& points, const glm::dvec3& up, double ceiling,
                        int width);
// Level, looking across the points' longer horizontal extent (up is +y).
MapView view_from_side(const std::vector<glm::dvec3>& points, int width);

// Image position (pixels, origin top-left, y down) of p in the view; `visible` false when p is
// behind the camera.
glm::dvec2 project(const MapView& view, const glm::dvec3& p, bool* visible = nullptr);

}  // namespace sdfreel::draw
