#include "draw/canvas.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "draw/bitmap_font.h"
#include "io/atomic_file.h"
#include "io/png_file.h"

namespace sdfreel::draw {

namespace {

// Distance from p to the segment a-b.
float segment_distance(float px, float py, float ax, float ay, float bx, float by) {
  const float dx = bx - ax, dy = by - ay;
  const float len2 = dx * dx + dy * dy;
  float t = len2 > 0.0f ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0f;
  t = std::clamp(t, 0.0f, 1.0f);
  const float qx = ax + t * dx - px, qy = ay + t * dy - py;
  return std::sqrt(qx * qx + qy * qy);
}

// Coverage of a pixel whose centre is `d` pixels inside (negative: outside) an edge.
float coverage(float d) {
  return std::clamp(d + 0.5f, 0.0f, 1.0f);
}

}  // namespace

Canvas::Canvas(int width, int height, Rgb background)
    : w_(width), h_(height), px_(size_t(width) * height * 3) {
  for (size_t i = 0; i < px_.size(); i += 3) {
    px_[i] = background.r;
    px_[i + 1] = background.g;
    px_[i + 2] = background.b;
  }
}

Rgb Canvas::at(int x, int y) const {
  const float* p = &px_[(size_t(y) * w_ + x) * 3];
  return {p[0], p[1], p[2]};
}

void Canvas::blend(int x, int y, Rgb c, float a) {
  if (x < 0 || y < 0 || x >= w_ || y >= h_ || a <= 0.0f) return;
  a = std::min(a, 1.0f);
  float* p = &px_[(size_t(y) * w_ + x) * 3];
  p[0] += (c.r - p[0]) * a;
  p[1] += (c.g - p[1]) * a;
  p[2] += (c.b - p[2]) * a;
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::max(y0, 0); y < std::min(y1, h_); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, w_); ++x) blend(x, y, c, 1.0f);
}

void Canvas::image(int x, int y, const ImageRGB16& img) {
  for (int iy = std::max(0, -y); iy < img.height && y + iy < h_; ++iy)
    for (int ix = std::max(0, -x); ix < img.width && x + ix < w_; ++ix)
      for (int c = 0; c < 3; ++c)
        px_[(size_t(y + iy) * w_ + (x + ix)) * 3 + c] =
            float(img.pixels[(size_t(iy) * img.width + ix) * 3 + c]) / 65535.0f;
}

void Canvas::line(float x0, float y0, float x1, float y1, float width, Rgb c) {
  const float r = 0.5f * width;
  const int xa = int(std::floor(std::min(x0, x1) - r - 1)),
            xb = int(std::ceil(std::max(x0, x1) + r + 1));
  const int ya = int(std::floor(std::min(y0, y1) - r - 1)),
            yb = int(std::ceil(std::max(y0, y1) + r + 1));
  for (int y = ya; y <= yb; ++y)
    for (int x = xa; x <= xb; ++x)
      blend(x, y, c, coverage(r - segment_distance(x + 0.5f, y + 0.5f, x0, y0, x1, y1)));
}

void Canvas::disc(float cx, float cy, float radius, Rgb c) {
  for (int y = int(cy - radius - 2); y <= int(cy + radius + 2); ++y)
    for (int x = int(cx - radius - 2); x <= int(cx + radius + 2); ++x) {
      const float d = std::hypot(x + 0.5f - cx, y + 0.5f - cy);
      blend(x, y, c, coverage(radius - d));
    }
}

void Canvas::ring(float cx, float cy, float radius, float width, Rgb c) {
  for (int y = int(cy - radius - width - 2); y <= int(cy + radius + width + 2); ++y)
    for (int x = int(cx - radius - width - 2); x <= int(cx + radius + width + 2); ++x) {
      const float d = std::hypot(x + 0.5f - cx, y + 0.5f - cy);
      blend(x, y, c, coverage(0.5f * width - std::abs(d - radius)));
    }
}

int Canvas::text_width(const std::string& s) {
  return int(s.size()) * GLYPH_WIDTH;
}

int Canvas::text(int x, int y, const std::string& s, Rgb c, bool vertical) {
  for (size_t i = 0; i < s.size(); ++i)
    for (int gy = 0; gy < GLYPH_HEIGHT; ++gy)
      for (int gx = 0; gx < GLYPH_WIDTH; ++gx) {
        const float a = glyph_coverage(s[i], gx, gy);
        if (a <= 0.0f) continue;
        const int along = int(i) * GLYPH_WIDTH + gx;
        if (vertical)
          blend(x + gy, y - along, c, a);
        else
          blend(x + along, y + gy, c, a);
      }
  return text_width(s);
}

void Canvas::write_png(const std::string& path) const {
  std::vector<uint8_t> bytes(px_.size());
  for (size_t i = 0; i < px_.size(); ++i)
    bytes[i] = uint8_t(std::lround(std::clamp(px_[i], 0.0f, 1.0f) * 255.0f));
  try {
    const std::vector<unsigned char> png = encode_png(w_, h_, 3, 8, bytes.data(), {6, -1, 0});
    write_file_atomic(path, png.data(), png.size());
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
}

}  // namespace sdfreel::draw
