// The views of `sdfreel map`: fitted to the path, looking down the scene's up axis (or level from
// the side), under a ceiling where there is one, and projecting points where primary_ray_dir
// traces them (so marks sit on what the scene's renderer drew).
#include "draw/map_views.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "draw/path_map.h"
#include "support/solid_image.h"

namespace sdfreel::draw {
namespace {

// A path along z, low over the ground, with a bend in x.
const std::vector<glm::dvec3> kPath = {
    {0.9, 0.35, -0.9}, {-0.9, 0.3, 1.6}, {0.3, 0.28, 3.9}, {0.6, 0.4, 5.8}, {1.2, 1.3, 9.5}};

bool inside(const MapView& v, const glm::dvec3& p) {
  bool visible = false;
  const glm::dvec2 q = project(v, p, &visible);
  return visible && q.x >= 0 && q.x <= v.width && q.y >= 0 && q.y <= v.height;
}

TEST(MapViews, FromAboveLooksStraightDownAndShowsEveryPoint) {
  const MapView v = view_from_above(kPath, {0, 1, 0}, 1e9, 960);
  EXPECT_EQ(v.width, 960);
  EXPECT_GT(v.height, 0.35 * 960 - 2);  // a long path: a tall map, within the allowed aspects
  EXPECT_LE(v.height, 960);
  const glm::dvec3 d = glm::normalize(v.pose.target - v.pose.position);
  EXPECT_NEAR(d.y, -1.0, 1e-12);
  EXPECT_GT(v.pose.position.y, 1.3);  // above the highest point
  for (const glm::dvec3& p : kPath) EXPECT_TRUE(inside(v, p)) << p.x << " " << p.z;
  // The path fills most of the long side, not a corner of it.
  const double z0 = project(v, kPath.front()).y, z1 = project(v, kPath.back()).y;
  EXPECT_GT(std::abs(z1 - z0), 0.6 * v.height);
}

TEST(MapViews, UnderACeilingComesNoHigherAndWidens) {
  const MapView free = view_from_above(kPath, {0, 1, 0}, 1e9, 640);
  const MapView low = view_from_above(kPath, {0, 1, 0}, 3.95, 640);
  EXPECT_LE(low.pose.position.y, 3.95 + 1e-9);
  EXPECT_GT(low.pose.fov_deg, free.pose.fov_deg);
  for (const glm::dvec3& p : kPath) EXPECT_TRUE(inside(low, p));
}

TEST(MapViews, AnotherUpAxisLooksAlongIt) {
  // light_beams: the world is the plane z = 0, seen from +z.
  const std::vector<glm::dvec3> path = {{-1, 0, 1}, {2, 0.5, 1.2}};
  const MapView v = view_from_above(path, {0, 0, 1}, 1e9, 400);
  const glm::dvec3 d = glm::normalize(v.pose.target - v.pose.position);
  EXPECT_NEAR(d.z, -1.0, 1e-12);
  for (const glm::dvec3& p : path) EXPECT_TRUE(inside(v, p));
}

TEST(MapViews, FromTheSideIsLevelAndAcrossTheLongerExtent) {
  const MapView v = view_from_side(kPath, 960);
  const glm::dvec3 d = glm::normalize(v.pose.target - v.pose.position);
  EXPECT_NEAR(d.y, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(d.x), 1.0, 1e-12);  // the path runs along z: looked at along x
  for (const glm::dvec3& p : kPath) EXPECT_TRUE(inside(v, p));
}

// The ray primary_ray_dir traces through a point's projected pixel passes through the point.
TEST(MapViews, ProjectsWhereTheRendererTraces) {
  const MapView v = view_from_above(kPath, {0, 1, 0}, 1e9, 320);
  const CameraBasis b = make_camera_basis(v.pose);
  for (const glm::dvec3& p : kPath) {
    const glm::dvec2 q = project(v, p);
    const glm::dvec3 dir(primary_ray_dir(b, float(q.x), float(q.y), v.width, v.height));
    const glm::dvec3 to = glm::normalize(p - v.pose.position);
    EXPECT_GT(glm::dot(dir, to), 1.0 - 1e-6) << p.x << " " << p.z;
  }
}

// The first key is drawn in its colour where its point projects, on top of the scene's image.
TEST(PathMap, DrawsTheKeysWhereTheyProject) {
  const MapView v = view_from_above(kPath, {0, 1, 0}, 1e9, 320);
  PathMarks m;
  m.path = kPath;
  for (size_t i = 0; i < kPath.size(); ++i) m.keys.push_back({double(i), kPath[i], {0, 0, 1}});
  const Canvas c = path_map({{v, test::solid_frame(v.width, v.height, 0, 0, 65535)}}, m, "t");
  const int x0 = 8, y0 = 8 + 13 + 8;  // gap, title line, gap
  EXPECT_EQ(c.width(), 320 + 16);
  const glm::dvec2 first = project(v, kPath.front()), last = project(v, kPath.back());
  const Rgb a = c.at(x0 + int(first.x), y0 + int(first.y));
  const Rgb b = c.at(x0 + int(last.x), y0 + int(last.y));
  EXPECT_GT(a.g, 0.8f);  // green: the start
  EXPECT_LT(a.b, 0.5f);
  EXPECT_GT(b.r, 0.9f);  // red: the end
  EXPECT_LT(b.b, 0.5f);
  const Rgb far = c.at(x0 + 2, y0 + 2);  // the scene's own pixel where nothing is drawn
  EXPECT_EQ(far.b, 1.0f);
}

// Keys that project close together (as from the side) get their labels one under another, not
// printed over each other: the last key's red label lies below the first key's green one.
TEST(PathMap, LabelsOfNearbyKeysDoNotOverlap) {
  const MapView v = view_from_above(kPath, {0, 1, 0}, 1e9, 320);
  PathMarks m;
  m.path = kPath;
  m.keys = {{0.0, {0.3, 0.3, 3.9}, {0, 0, 1}}, {12.0, {0.3, 0.3, 3.9001}, {0, 0, 1}}};
  const Canvas c = path_map({{v, test::solid_frame(v.width, v.height, 0, 0, 0)}}, m, "t");
  const glm::dvec2 q = project(v, m.keys[0].position) + glm::dvec2(8, 8 + 13 + 8);
  int green_bottom = -1, red_top = 1 << 30;
  for (int y = int(q.y) - 20; y < int(q.y) + 40; ++y)
    for (int x = int(q.x) + 8; x < int(q.x) + 60; ++x) {
      const Rgb p = c.at(x, y);
      if (p.g > 0.8f && p.r < 0.5f) green_bottom = std::max(green_bottom, y);
      if (p.r > 0.9f && p.g < 0.5f) red_top = std::min(red_top, y);
    }
  ASSERT_GE(green_bottom, 0);
  ASSERT_LT(red_top, 1 << 30);
  EXPECT_GT(red_top, green_bottom);
}

}  // namespace
}  // namespace sdfreel::draw
