#pragma once
// 3x3 colour matrices built from primaries (CIE xy), in double: RGB <-> XYZ and Bradford white
// adaptation, the way OpenColorIO builds the matrices of its BuiltinTransforms. Only + - * / are
// used, so every build computes the same bits.
#include <glm/vec3.hpp>

namespace sdfreel {

struct V3x8;

struct Chromaticity {
  double x, y;
};

struct Primaries {
  Chromaticity red, green, blue, white;
};

extern const Primaries kAcesAp0;  // ACES2065-1
extern const Primaries kAcesAp1;  // ACEScg
extern const Primaries kRec709;   // sRGB / Rec.709, D65 white

struct Mat3 {
  double m[3][3];  // row-major: out[i] = sum_j m[i][j] * in[j]
};

Mat3 operator*(const Mat3& a, const Mat3& b);
Mat3 inverse(const Mat3& a);

Mat3 rgb_to_xyz(const Primaries& p);
// XYZ of white `from` -> XYZ of white `to` (Bradford cone response).
Mat3 bradford(const Chromaticity& from, const Chromaticity& to);
// RGB of `src` -> RGB of `dst`, adapting src's white to dst's by Bradford when `adapt`.
Mat3 rgb_to_rgb(const Primaries& src, const Primaries& dst, bool adapt);

// The matrix rounded to float and applied in float, in a fixed order (as OCIO's CPU matrix op).
struct FloatMat3 {
  float m[3][3];
  explicit FloatMat3(const Mat3& d);
  glm::vec3 operator()(const glm::vec3& v) const;
  V3x8 operator()(const V3x8& v) const;  // eight pixels, each with the bits of the line above
};

}  // namespace sdfreel
