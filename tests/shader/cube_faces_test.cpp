// A cubemap channel's faces (shader/cube_faces.h): six files as given, the cells of a horizontal
// and a vertical cross (the vertical one's -z upside down), and an equirect panorama resampled
// so that each face looks where GL's cube sampling looks.
#include "shader/cube_faces.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace sdfreel {
namespace {

// A w x h image whose cell (column, row) of size n is filled with the value 10 * column + row.
ImageRGBA cells(int w, int h, int n) {
  ImageRGBA image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = image.at(x, y);
      p[0] = float(10 * (x / n) + y / n);
      p[1] = float(x % n);  // where in the cell, to see a cell turned over
      p[2] = float(y % n);
      p[3] = 1.0f;
    }
  return image;
}

TEST(CubeFaces, HorizontalCrossCells) {
  const CubeFaces cube = cube_from_image(cells(16, 12, 4));
  ASSERT_EQ(cube.size, 4);
  // +x (2,1), -x (0,1), +y (1,0), -y (1,2), +z (1,1), -z (3,1), each as stored.
  const float want[6] = {21, 1, 10, 12, 11, 31};
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(cube.faces[f].at(0, 0)[0], want[f]) << f;
    EXPECT_EQ(cube.faces[f].at(3, 1)[1], 3.0f);
    EXPECT_EQ(cube.faces[f].at(3, 1)[2], 1.0f);
  }
}

TEST(CubeFaces, VerticalCrossTurnsMinusZOver) {
  const CubeFaces cube = cube_from_image(cells(12, 16, 4));
  const float want[6] = {21, 1, 10, 12, 11, 13};
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(cube.faces[f].at(0, 0)[0], want[f]) << f;
  EXPECT_EQ(cube.faces[5].at(0, 0)[1], 3.0f);  // -z: its cell's last column and row first
  EXPECT_EQ(cube.faces[5].at(0, 0)[2], 3.0f);
}

TEST(CubeFaces, EquirectLooksWhereTheFacesLook) {
  // A 64x32 panorama: red grows to the right (longitude), green downwards (latitude).
  ImageRGBA pano(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      float* p = pano.at(x, y);
      p[0] = (float(x) + 0.5f) / 64.0f;
      p[1] = (float(y) + 0.5f) / 32.0f;
      p[3] = 1.0f;
    }
  const CubeFaces cube = cube_from_image(pano);
  ASSERT_EQ(cube.size, 16);
  auto centre = [&](int f) {
    const float* a = cube.faces[size_t(f)].at(7, 7);
    const float* b = cube.faces[size_t(f)].at(8, 8);
    return std::pair<float, float>{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
  };
  EXPECT_NEAR(centre(5).first, 0.5f, 0.02f);   // -z: the panorama's centre
  EXPECT_NEAR(centre(0).first, 0.75f, 0.02f);  // +x: a quarter turn to the right
  EXPECT_NEAR(centre(1).first, 0.25f, 0.02f);  // -x
  EXPECT_NEAR(centre(5).second, 0.5f, 0.02f);  // on the horizon
  EXPECT_LT(centre(2).second, 0.1f);           // +y: the top rows
  EXPECT_GT(centre(3).second, 0.9f);           // -y: the bottom rows
  // Up on the side faces is row 0, as GL samples them.
  EXPECT_LT(cube.faces[0].at(8, 0)[1], cube.faces[0].at(8, 15)[1]);
}

TEST(CubeFaces, RefusesWhatIsNotACube) {
  EXPECT_THROW(cube_from_image(ImageRGBA(30, 20)), std::runtime_error);
  std::array<ImageRGBA, 6> faces;
  for (ImageRGBA& f : faces) f = ImageRGBA(8, 8);
  faces[3] = ImageRGBA(8, 4);
  try {
    cube_from_faces(faces, {"a", "b", "c", "d.png", "e", "f"});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("face -y (d.png) is 8x4"), std::string::npos) << e.what();
  }
  faces[3] = ImageRGBA(4, 4);
  EXPECT_THROW(cube_from_faces(faces, {}), std::runtime_error);
  faces[3] = ImageRGBA(8, 8);
  EXPECT_EQ(cube_from_faces(faces, {}).size, 8);
}

}  // namespace
}  // namespace sdfreel
