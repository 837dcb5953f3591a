// The pictures on the hall's walls are paintings, not flat colours: each canvas shows a landscape
// in its own colours (a pale sky, a sun, darker hills below), the right way round from the room,
// and the hall's shading uses it.
#include "scenes/museum/paintings.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "scenes/museum/hall_layout.h"
#include "scenes/museum/lighting.h"

namespace sdfreel {
namespace {

using namespace museum;
using glm::vec3;

// The point of canvas k at (u, v) in [0, 1]^2 as seen from the room (u to the right, v up).
vec3 canvas_point(int k, float u, float v) {
  const Painting& p = painting(k);
  const float x = p.side > 0.0f ? p.x + CANVAS_HALF_W - 2.0f * CANVAS_HALF_W * u
                                : p.x - CANVAS_HALF_W + 2.0f * CANVAS_HALF_W * u;
  return vec3(x, CANVAS_Y0 + (CANVAS_Y1 - CANVAS_Y0) * v, p.side * (ROOM_Z - 0.06f));
}

float luminance(const vec3& c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

TEST(MuseumPaintings, EachCanvasIsALandscapeInItsOwnColours) {
  for (int k = 0; k < PAINTING_COUNT; ++k) {
    std::set<std::tuple<float, float, float>> colours;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 30; ++j) {
        const vec3 c = painting_albedo(canvas_point(k, float(i) / 40.0f, float(j) / 30.0f), k);
        ASSERT_GE(c.r, 0.0f);
        ASSERT_LT(glm::max(c.r, glm::max(c.g, c.b)), 1.0f);  // an albedo
        colours.insert({c.r, c.g, c.b});
      }
    EXPECT_GT(colours.size(), 100u) << "painting " << k;
    // The sun to the upper right, brighter than the sky beside it; the hills below, darker.
    const float sun = luminance(painting_albedo(canvas_point(k, 0.7f, 0.74f), k));
    const float sky = luminance(painting_albedo(canvas_point(k, 0.3f, 0.9f), k));
    const float hills = luminance(painting_albedo(canvas_point(k, 0.5f, 0.05f), k));
    EXPECT_GT(sun, sky) << k;
    EXPECT_LT(hills, 0.7f * sky) << k;
  }
  // Each in its own colours: at the same place of the canvas no two are alike.
  std::set<std::tuple<float, float, float>> hills;
  for (int k = 0; k < PAINTING_COUNT; ++k) {
    const vec3 c = painting_albedo(canvas_point(k, 0.5f, 0.02f), k);
    hills.insert({c.r, c.g, c.b});
  }
  EXPECT_EQ(hills.size(), size_t(PAINTING_COUNT));
}

// The hall's boxes hang every painting with its material, and its shading reads the canvas.
TEST(MuseumPaintings, TheHallHangsThemAndShadesThem) {
  int canvases = 0;
  for (const HallBox& b : hall_boxes()) {
    if (b.material < MATERIAL_PAINTING) continue;
    const int k = int(b.material - MATERIAL_PAINTING);
    ASSERT_LT(k, PAINTING_COUNT);
    ++canvases;
    const vec3 normal(0.0f, 0.0f, -painting(k).side);  // into the room
    const HallLight light{vec3(0.0f, 1.7f, 0.0f), {}};
    const vec3 sun = canvas_point(k, 0.7f, 0.74f), hill = canvas_point(k, 0.5f, 0.05f);
    EXPECT_GT(luminance(hall_radiance(sun, normal, b.albedo, b.material, light, SunMap{})),
              luminance(hall_radiance(hill, normal, b.albedo, b.material, light, SunMap{})))
        << k;
  }
  EXPECT_EQ(canvases, PAINTING_COUNT);
}

}  // namespace
}  // namespace sdfreel
