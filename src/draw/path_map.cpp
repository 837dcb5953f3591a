#include "draw/path_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "draw/bitmap_font.h"

namespace sdfreel::draw {
namespace {

constexpr int kGap = 8;
constexpr int kCaptionHeight = GLYPH_HEIGHT + 6;
const Rgb kBackground{0.11f, 0.11f, 0.12f}, kText{0.88f, 0.88f, 0.88f};
const Rgb kShadow{0.0f, 0.0f, 0.0f}, kPath{1.0f, 0.82f, 0.2f}, kKey{1.0f, 1.0f, 1.0f};
const Rgb kStart{0.3f, 0.9f, 0.4f}, kEnd{0.95f, 0.3f, 0.3f}, kLook{0.35f, 0.85f, 1.0f};

// Draws on one panel of the canvas, in the panel's image coordinates.
struct Panel {
  Canvas& c;
  int x0, y0;
  const MapView& v;

  bool at(const glm::dvec3& p, glm::dvec2& out) const {
    bool visible = false;
    out = project(v, p, &visible) + glm::dvec2(x0, y0);
    // Far outside the panel a point is not drawn (a line there would only cost time).
    return visible && out.x > x0 - v.width && out.x < x0 + 2 * v.width && out.y > y0 - v.height &&
           out.y < y0 + 2 * v.height;
  }
  void line(const glm::dvec3& a, const glm::dvec3& b, float width, Rgb colour) const {
    glm::dvec2 pa, pb;
    if (at(a, pa) && at(b, pb))
      c.line(float(pa.x), float(pa.y), float(pb.x), float(pb.y), width, colour);
  }
  // A line with a dark edge, readable over a bright or a dark scene.
  void stroke(const glm::dvec3& a, const glm::dvec3& b, float width, Rgb colour) const {
    line(a, b, width + 2.0f, kShadow);
    line(a, b, width, colour);
  }
  // A dot; with a label beside it, moved down a line at a time past the labels in `taken` (keys
  // that project close together, as from the side, would otherwise print over each other).
  void dot(const glm::dvec3& p, float radius, Rgb colour, const std::string& label = "",
           std::vector<glm::ivec4>* taken = nullptr) const {
    glm::dvec2 q;
    if (!at(p, q)) return;
    c.disc(float(q.x), float(q.y), radius + 1.5f, kShadow);
    c.disc(float(q.x), float(q.y), radius, colour);
    if (label.empty()) return;
    const int tx = int(q.x) + int(radius) + 3, w = Canvas::text_width(label);
    int ty = int(q.y) - GLYPH_HEIGHT / 2;
    for (bool moved = true; moved && taken;) {
      moved = false;
      for (const glm::ivec4& r : *taken)
        if (tx < r.z && r.x < tx + w && ty < r.w && r.y < ty + GLYPH_HEIGHT) {
          ty = r.w + 1;
          moved = true;
        }
    }
    if (taken) taken->push_back({tx, ty, tx + w, ty + GLYPH_HEIGHT});
    for (int dy = -1; dy <= 1; ++dy)  // a dark halo under the text
      for (int dx = -1; dx <= 1; ++dx) c.text(tx + dx, ty + dy, label, kShadow);
    c.text(tx, ty, label, colour);
  }
};

std::string seconds_label(double t) {
  char s[32];
  std::snprintf(s, sizeof s, "%g s", std::round(t * 100.0) / 100.0);
  return s;
}

// A bar of a round length (0.1, 0.2, 0.5, 1, 2, 5... units) about 80 pixels long, with its label.
void scale_bar(Canvas& c, int x, int y, double units_per_pixel) {
  const double want = 80.0 * units_per_pixel;
  const double p10 = std::pow(10.0, std::floor(std::log10(want)));
  double len = p10;
  for (double m : {2.0, 5.0, 10.0})
    if (p10 * m <= want) len = p10 * m;
  const float px = float(len / units_per_pixel);
  c.fill_rect(x, y + GLYPH_HEIGHT / 2 - 1, x + int(px), y + GLYPH_HEIGHT / 2 + 2, kText);
  char s[48];
  std::snprintf(s, sizeof s, "%g unit%s", len, len == 1.0 ? "" : "s");
  c.text(x + int(px) + 6, y, s, kText);
}

// The world's axes in a corner of the panel: where +x, +y and +z point at the centre of this
// view (those seen end-on are left out).
void axes(const Panel& p) {
  const glm::dvec3 centre = p.v.pose.target;
  const glm::dvec2 corner(p.x0 + 40, p.y0 + p.v.height - 40);
  const glm::dvec2 origin = project(p.v, centre);
  const struct {
    glm::dvec3 dir;
    const char* name;
  } world[] = {{{1, 0, 0}, "+x"}, {{0, 1, 0}, "+y"}, {{0, 0, 1}, "+z"}};
  for (const auto& a : world) {
    const glm::dvec2 d = project(p.v, centre + a.dir * (p.v.units_per_pixel * 10.0)) - origin;
    const double len = glm::length(d);
    if (len < 3.0) continue;  // seen end-on
    const glm::dvec2 tip = corner + d / len * 26.0;
    p.c.line(float(corner.x), float(corner.y), float(tip.x), float(tip.y), 3.0f, kShadow);
    p.c.line(float(corner.x), float(corner.y), float(tip.x), float(tip.y), 1.5f, kText);
    p.c.text(int(tip.x + d.x / len * 8.0) - 6, int(tip.y + d.y / len * 8.0) - GLYPH_HEIGHT / 2,
             a.name, kText);
  }
}

void draw_marks(const Panel& p, const PathMarks& m) {
  for (size_t i = 1; i < m.path.size(); ++i) p.stroke(m.path[i - 1], m.path[i], 2.0f, kPath);
  // The camera's direction each second, as long as 24 pixels at the path's nearest point.
  const double look = 24.0 * p.v.units_per_pixel;
  for (const PathPoint& s : m.seconds) {
    p.stroke(s.position, s.position + s.forward * look, 1.5f, kLook);
    p.dot(s.position, 2.0f, kPath);
  }
  std::vector<glm::ivec4> labels;  // x0, y0, x1, y1 of each key's label
  for (size_t i = 0; i < m.keys.size(); ++i) {
    // Keys at one place (a loop that ends where it starts) share a dot: "0 s, 10 s".
    bool seen = false;
    for (size_t j = 0; j < i && !seen; ++j) seen = m.keys[j].position == m.keys[i].position;
    if (seen) continue;
    std::string label = seconds_label(m.keys[i].t);
    for (size_t j = i + 1; j < m.keys.size(); ++j)
      if (m.keys[j].position == m.keys[i].position) label += ", " + seconds_label(m.keys[j].t);
    const Rgb colour = i == 0 ? kStart : i + 1 == m.keys.size() ? kEnd : kKey;
    p.stroke(m.keys[i].position, m.keys[i].position + m.keys[i].forward * look, 2.0f, kLook);
    p.dot(m.keys[i].position, 4.5f, colour, label, &labels);
  }
}

}  // namespace

Canvas path_map(const std::vector<MapPanel>& panels, const PathMarks& marks,
                const std::string& title) {
  int width = 2 * kGap + Canvas::text_width(title), height = kGap + GLYPH_HEIGHT + kGap;
  for (const MapPanel& p : panels) {
    width = std::max(width, 2 * kGap + p.image.width);
    height += p.image.height + kCaptionHeight + kGap;
  }
  Canvas c(width, height, kBackground);
  c.text(kGap, kGap, title, kText);
  int y = kGap + GLYPH_HEIGHT + kGap;
  for (const MapPanel& mp : panels) {
    c.image(kGap, y, mp.image);
    const Panel p{c, kGap, y, mp.view};
    draw_marks(p, marks);
    axes(p);
    const int caption = y + mp.image.height + 3;
    const int advance = c.text(kGap, caption, mp.view.name + "   ", kText);
    scale_bar(c, kGap + advance, caption, mp.view.units_per_pixel);
    y += mp.image.height + kCaptionHeight + kGap;
  }
  return c;
}

}  // namespace sdfreel::draw
