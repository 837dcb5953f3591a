#include "io/color_matrices.h"

#include "sdf/lanes.h"

namespace sdfreel {

const Primaries kAcesAp0{{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}, {0.32168, 0.33767}};
const Primaries kAcesAp1{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}, {0.32168, 0.33767}};
const Primaries kRec709{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}};

namespace {

struct Vec3d {
  double v[3];
};

Vec3d xyz_of(const Chromaticity& c) {
  return {{c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y}};
}

Vec3d apply(const Mat3& a, const Vec3d& x) {
  Vec3d out{};
  for (int i = 0; i < 3; ++i)
    out.v[i] = a.m[i][0] * x.v[0] + a.m[i][1] * x.v[1] + a.m[i][2] * x.v[2];
  return out;
}

Mat3 diagonal(const Vec3d& d) {
  return {{{d.v[0], 0, 0}, {0, d.v[1], 0}, {0, 0, d.v[2]}}};
}

}  // namespace

Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      out.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  return out;
}

// Cofactors over the determinant.
Mat3 inverse(const Mat3& a) {
  const auto& m = a.m;
  Mat3 c{};
  c.m[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  c.m[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
  c.m[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
  c.m[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  c.m[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
  c.m[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
  c.m[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  c.m[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
  c.m[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  const double det = m[0][0] * c.m[0][0] + m[0][1] * c.m[1][0] + m[0][2] * c.m[2][0];
  for (auto& row : c.m)
    for (double& e : row) e /= det;
  return c;
}

// Columns are the primaries' XYZ, scaled so that RGB (1,1,1) is the white with Y = 1.
Mat3 rgb_to_xyz(const Primaries& p) {
  const Vec3d r = xyz_of(p.red), g = xyz_of(p.green), b = xyz_of(p.blue);
  const Mat3 cols{{{r.v[0], g.v[0], b.v[0]}, {r.v[1], g.v[1], b.v[1]}, {r.v[2], g.v[2], b.v[2]}}};
  const Vec3d s = apply(inverse(cols), xyz_of(p.white));
  return cols * diagonal(s);
}

Mat3 bradford(const Chromaticity& from, const Chromaticity& to) {
  const Mat3 cone{
      {{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
  const Vec3d src = apply(cone, xyz_of(from)), dst = apply(cone, xyz_of(to));
  const Vec3d gain{{dst.v[0] / src.v[0], dst.v[1] / src.v[1], dst.v[2] / src.v[2]}};
  return inverse(cone) * diagonal(gain) * cone;
}

Mat3 rgb_to_rgb(const Primaries& src, const Primaries& dst, bool adapt) {
  const Mat3 to_xyz = rgb_to_xyz(src);
  const Mat3 from_xyz = inverse(rgb_to_xyz(dst));
  if (!adapt) return from_xyz * to_xyz;
  return from_xyz * bradford(src.white, dst.white) * to_xyz;
}

FloatMat3::FloatMat3(const Mat3& d) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = float(d.m[i][j]);
}

glm::vec3 FloatMat3::operator()(const glm::vec3& v) const {
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z;
  return out;
}

V3x8 FloatMat3::operator()(const V3x8& v) const {
  const auto row = [&](int i) { return m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z; };
  return {row(0), row(1), row(2)};
}

}  // namespace sdfreel
