#include "shader/cube_faces.h"

#include <stdexcept>

#include "sdf/cube_layout.h"
#include "sdf/det_math.h"

namespace sdfreel {

namespace {

constexpr const char* kFaceNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};

// The size x size square of `image` at (x0, y0), rotated by 180 degrees when `flip`.
ImageRGBA crop(const ImageRGBA& image, int x0, int y0, int size, bool flip) {
  ImageRGBA face(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const int sx = flip ? x0 + size - 1 - x : x0 + x, sy = flip ? y0 + size - 1 - y : y0 + y;
      std::copy(image.at(sx, sy), image.at(sx, sy) + 4, face.at(x, y));
    }
  return face;
}

// GL's direction through texel (x, y) of `face`.
glm::vec3 face_direction(int face, int x, int y, int size) {
  return cube_face_direction(face, 2.0f * (float(x) + 0.5f) / float(size) - 1.0f,
                             2.0f * (float(y) + 0.5f) / float(size) - 1.0f);
}

// Bilinear sample of an equirect image at (u, v) in texels' units, wrapping around in u.
void sample_equirect(const ImageRGBA& image, float u, float v, float* out) {
  const float fx = u - 0.5f, fy = dm::clamp(v - 0.5f, 0.0f, float(image.height - 1));
  const int x0 = int(dm::floor(fx)), y0 = int(dm::floor(fy));
  const float ax = fx - float(x0), ay = fy - float(y0);
  const int y1 = y0 + 1 < image.height ? y0 + 1 : y0;
  auto wrap = [&](int x) { return ((x % image.width) + image.width) % image.width; };
  const float* p00 = image.at(wrap(x0), y0);
  const float* p10 = image.at(wrap(x0 + 1), y0);
  const float* p01 = image.at(wrap(x0), y1);
  const float* p11 = image.at(wrap(x0 + 1), y1);
  for (int c = 0; c < 4; ++c) {
    const float top = p00[c] + (p10[c] - p00[c]) * ax;
    const float bottom = p01[c] + (p11[c] - p01[c]) * ax;
    out[c] = top + (bottom - top) * ay;
  }
}

CubeFaces from_equirect(const ImageRGBA& image) {
  CubeFaces cube;
  cube.size = image.width / 4;
  const float two_pi = 6.28318530718f, pi = 3.14159265359f;
  for (int f = 0; f < 6; ++f) {
    cube.faces[size_t(f)] = ImageRGBA(cube.size, cube.size);
    for (int y = 0; y < cube.size; ++y)
      for (int x = 0; x < cube.size; ++x) {
        const glm::vec3 d = face_direction(f, x, y, cube.size);
        const float len = dm::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        const float lon = dm::atan2(d.x, -d.z), lat = dm::asin(dm::clamp(d.y / len, -1.0f, 1.0f));
        sample_equirect(image, (0.5f + lon / two_pi) * float(image.width),
                        (0.5f - lat / pi) * float(image.height), cube.faces[size_t(f)].at(x, y));
      }
  }
  return cube;
}

}  // namespace

CubeFaces cube_from_faces(std::array<ImageRGBA, 6> faces, const std::vector<std::string>& names) {
  CubeFaces cube;
  cube.size = faces[0].width;
  for (size_t f = 0; f < 6; ++f) {
    const ImageRGBA& face = faces[f];
    const std::string name = f < names.size() ? names[f] : kFaceNames[f];
    if (face.width != face.height)
      throw std::runtime_error("face " + std::string(kFaceNames[f]) + " (" + name + ") is " +
                               std::to_string(face.width) + "x" + std::to_string(face.height) +
                               ": cube faces are square");
    if (face.width != cube.size)
      throw std::runtime_error("face " + std::string(kFaceNames[f]) + " (" + name + ") is " +
                               std::to_string(face.width) + " texels wide, face +x " +
                               std::to_string(cube.size) + ": all six are the same size");
  }
  cube.faces = std::move(faces);
  return cube;
}

CubeFaces cube_from_image(const ImageRGBA& image) {
  const int w = image.width, h = image.height;
  if (w == 2 * h && w % 4 == 0) return from_equirect(image);
  const bool horizontal = w * 3 == h * 4 && w % 4 == 0;
  const bool vertical = w * 4 == h * 3 && w % 3 == 0;
  if (!horizontal && !vertical)
    throw std::runtime_error("a " + std::to_string(w) + "x" + std::to_string(h) +
                             " image is neither a cross (4:3 or 3:4) nor an equirect panorama "
                             "(2:1); give six face files instead");
  CubeFaces cube;
  const int n = horizontal ? w / 4 : w / 3;
  cube.size = n;
  // Cells (column, row) of +x, -x, +y, -y, +z, -z.
  const int hx[6] = {2, 0, 1, 1, 1, 3}, hy[6] = {1, 1, 0, 2, 1, 1};
  const int vx[6] = {2, 0, 1, 1, 1, 1}, vy[6] = {1, 1, 0, 2, 1, 3};
  for (size_t f = 0; f < 6; ++f) {
    const int cx = horizontal ? hx[f] : vx[f], cy = horizontal ? hy[f] : vy[f];
    cube.faces[f] = crop(image, cx * n, cy * n, n, vertical && f == 5);
  }
  return cube;
}

}  // namespace sdfreel
