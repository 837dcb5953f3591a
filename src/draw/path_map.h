#pragma once
// The picture of `sdfreel map`: the scene rendered from each map view, with the camera path drawn
// over it (the eye at every frame), its keys labelled with their times, the camera's direction
// each second, the world's axes and a scale bar, under a title line.
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "draw/canvas.h"
#include "draw/map_views.h"
#include "render/image.h"

namespace sdfreel::draw {

struct PathPoint {
  double t = 0.0;  // video time, seconds
  glm::dvec3 position, forward;
};

struct PathMarks {
  std::vector<glm::dvec3> path;    // the eye at every frame, in order
  std::vector<PathPoint> keys;     // the timeline's camera keys
  std::vector<PathPoint> seconds;  // the camera at each whole second
};

struct MapPanel {
  MapView view;
  ImageRGB16 image;  // the scene from view.pose, view.width x view.height
};

Canvas path_map(const std::vector<MapPanel>& panels, const PathMarks& marks,
                const std::string& title);

}  // namespace sdfreel::draw
