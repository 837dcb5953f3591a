#pragma once
// A cubemap channel's six faces (docs/shaders.md), in GL's order +x, -x, +y, -y, +z, -z, each
// square with row 0 at the top as GL samples a cube face (so that the faces of the usual cross
// layouts upload as they are stored). Made from six image files, one cross or one equirect image.
#include <array>
#include <string>
#include <vector>

#include "render/image.h"

namespace sdfreel {

struct CubeFaces {
  int size = 0;
  std::array<ImageRGBA, 6> faces;
};

// Six files' texels, in face order. Throws std::runtime_error naming the face when one is not
// square or not the size of the first.
CubeFaces cube_from_faces(std::array<ImageRGBA, 6> faces, const std::vector<std::string>& names);

// One image: a horizontal cross (4:3; +y above +z; -x +z +x -z across; -y below), a vertical
// cross (3:4; +y, -x +z +x, -y, then -z upside down) or an equirect panorama (2:1; its centre
// looks down -z, +x to the right, up at the top), whose faces are width / 4 texels wide and
// sampled bilinearly with the project's deterministic math. Throws std::runtime_error otherwise.
CubeFaces cube_from_image(const ImageRGBA& image);

}  // namespace sdfreel
