#include "bench/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "draw/bitmap_font.h"
#include "draw/canvas.h"

namespace sdfreel::bench {
using draw::Canvas;
using draw::GLYPH_HEIGHT;
using draw::Rgb;

namespace {

constexpr int WIDTH = 1000, HEIGHT = 640;
constexpr int LEFT = 78, RIGHT = 24, TOP = 46, BOTTOM = 62;
const Rgb WHITE{1.0f, 1.0f, 1.0f}, BLACK{0.0f, 0.0f, 0.0f}, GRID{0.88f, 0.88f, 0.88f},
    MINOR_GRID{0.95f, 0.95f, 0.95f}, LABEL_GREY{0.35f, 0.35f, 0.35f};
const Rgb SERIES_COLOURS[] = {{0.12f, 0.40f, 0.75f}, {0.90f, 0.45f, 0.05f}, {0.2f, 0.6f, 0.2f}};
constexpr double INF_PSNR_MARGIN = 5.0;  // identical images plot this far above the best finite

std::string tick_label(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

struct Box {
  int x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

}  // namespace

void plot_speed_error(const std::vector<BenchRow>& rows, const std::string& title,
                      const std::string& path) {
  Canvas c(WIDTH, HEIGHT, WHITE);
  const int px0 = LEFT, px1 = WIDTH - RIGHT, py0 = TOP, py1 = HEIGHT - BOTTOM;

  // Ranges: x in decades around the data, y in steps of 5 dB.
  double smin = 1e30, smax = 0.0, pmin = 1e30, pmax = -1e30;
  for (const BenchRow& r : rows) {
    smin = std::min(smin, r.seconds_per_frame);
    smax = std::max(smax, r.seconds_per_frame);
    if (std::isfinite(r.psnr_db)) {
      pmin = std::min(pmin, r.psnr_db);
      pmax = std::max(pmax, r.psnr_db);
    }
  }
  if (rows.empty() || smax <= 0.0) smin = 0.01, smax = 1.0;
  if (pmin > pmax) pmin = 20.0, pmax = 50.0;
  const double inf_psnr = pmax + INF_PSNR_MARGIN;
  for (const BenchRow& r : rows)
    if (!std::isfinite(r.psnr_db)) pmax = inf_psnr;
  const double lx0 = std::floor(std::log10(std::max(smin, 1e-6)) * 4.0) / 4.0 - 0.05;
  const double lx1 = std::ceil(std::log10(std::max(smax, 1e-6)) * 4.0) / 4.0 + 0.05;
  const double y_lo = std::floor(pmin / 5.0) * 5.0, y_hi = std::ceil(pmax / 5.0 + 0.2) * 5.0;
  const auto X = [&](double s) {
    return float(px0 + (std::log10(std::max(s, 1e-9)) - lx0) / (lx1 - lx0) * (px1 - px0));
  };
  const auto Y = [&](double p) {
    if (!std::isfinite(p)) p = inf_psnr;
    return float(py1 - (p - y_lo) / (y_hi - y_lo) * (py1 - py0));
  };

  // Grid and tick labels.
  for (int d = int(std::floor(lx0)); d <= int(std::ceil(lx1)); ++d)
    for (int m = 1; m <= 9; ++m) {
      const double v = m * std::pow(10.0, d);
      const double lv = std::log10(v);
      if (lv < lx0 || lv > lx1) continue;
      const float x = X(v);
      const bool major = m == 1 || m == 2 || m == 5;
      c.line(x, float(py0), x, float(py1), 1.0f, major ? GRID : MINOR_GRID);
      if (major) {
        const std::string s = tick_label(v);
        c.text(int(x) - Canvas::text_width(s) / 2, py1 + 6, s, BLACK);
      }
    }
  const double y_step = (y_hi - y_lo) > 60.0 ? 10.0 : 5.0;
  for (double p = y_lo; p <= y_hi + 1e-9; p += y_step) {
    const float y = Y(p);
    c.line(float(px0), y, float(px1), y, 1.0f, GRID);
    const std::string s = tick_label(p);
    c.text(px0 - 8 - Canvas::text_width(s), int(y) - GLYPH_HEIGHT / 2, s, BLACK);
  }
  c.line(float(px0), float(py0), float(px0), float(py1), 1.5f, BLACK);
  c.line(float(px0), float(py1), float(px1), float(py1), 1.5f, BLACK);
  c.line(float(px1), float(py0), float(px1), float(py1), 1.0f, BLACK);
  c.line(float(px0), float(py0), float(px1), float(py0), 1.0f, BLACK);
  const std::string xlabel = "seconds per frame (log scale; left is faster)";
  c.text((px0 + px1 - Canvas::text_width(xlabel)) / 2, HEIGHT - 26, xlabel, BLACK);
  const std::string ylabel = "PSNR against the reference, dB (up is better)";
  c.text(14, (py0 + py1 + Canvas::text_width(ylabel)) / 2, ylabel, BLACK, true);
  c.text(px0, 14, title, BLACK);

  // Series: one per backend, in order of appearance.
  std::vector<std::string> backends;
  for (const BenchRow& r : rows)
    if (std::find(backends.begin(), backends.end(), r.backend) == backends.end())
      backends.push_back(r.backend);
  std::vector<Box> taken;
  for (size_t b = 0; b < backends.size(); ++b) {
    const Rgb col = SERIES_COLOURS[b % 3];
    std::vector<const BenchRow*> front;
    for (const BenchRow& r : rows)
      if (r.backend == backends[b] && r.on_front) front.push_back(&r);
    std::sort(front.begin(), front.end(), [](const BenchRow* a, const BenchRow* z) {
      return a->seconds_per_frame < z->seconds_per_frame;
    });
    for (size_t i = 1; i < front.size(); ++i)
      c.line(X(front[i - 1]->seconds_per_frame), Y(front[i - 1]->psnr_db),
             X(front[i]->seconds_per_frame), Y(front[i]->psnr_db), 1.5f, col);
    for (const BenchRow& r : rows) {
      if (r.backend != backends[b]) continue;
      const float x = X(r.seconds_per_frame), y = Y(r.psnr_db);
      c.disc(x, y, r.named_preset ? 5.0f : 3.5f, col);
      if (r.on_front) c.ring(x, y, 8.0f, 1.5f, col);
      taken.push_back(Box{int(x) - 5, int(y) - 5, int(x) + 5, int(y) + 5});
    }
  }
  // Labels: presets first (always drawn), then front points where there is room; the legend's
  // corner stays free.
  taken.push_back(Box{px0, py0, px0 + 200, py0 + 30 + 18 * int(backends.size())});
  std::vector<Box> labels;  // placed labels only: a preset's label may cover points, not text
  labels.push_back(taken.back());  // the legend
  const auto inside = [&](const Box& o) {
    return o.x0 >= px0 && o.x1 <= px1 && o.y0 >= py0 && o.y1 <= py1;
  };
  const auto free_of = [](const std::vector<Box>& boxes, const Box& o) {
    return std::none_of(boxes.begin(), boxes.end(), [&](const Box& t) { return t.overlaps(o); });
  };
  for (int pass = 0; pass < 2; ++pass)
    for (const BenchRow& r : rows) {
      if (pass == 0 ? !r.named_preset : (r.named_preset || !r.on_front)) continue;
      const std::string s = r.preset + (backends.size() > 1 ? " (" + r.backend + ")" : "");
      const int w = Canvas::text_width(s), x = int(X(r.seconds_per_frame)), y = int(Y(r.psnr_db));
      std::vector<Box> options;  // right or left of the point, from near to far above and below
      for (int dy : {-16, 4, -30, 18, -44, 32})
        for (int side = 0; side < 2; ++side) {
          const int x0 = side == 0 ? x + 10 : x - 10 - w;
          options.push_back(Box{x0, y + dy, x0 + w, y + dy + GLYPH_HEIGHT});
        }
      const Box* chosen = nullptr;
      for (const Box& o : options)
        if (!chosen && inside(o) && free_of(taken, o)) chosen = &o;
      // A preset's label is always drawn: clear of other labels if possible, inside the plot.
      for (const Box& o : options)
        if (!chosen && pass == 0 && inside(o) && free_of(labels, o)) chosen = &o;
      if (!chosen && pass == 0) chosen = &options[0];
      if (!chosen) continue;
      c.text(chosen->x0, chosen->y0, s, r.named_preset ? BLACK : LABEL_GREY);
      taken.push_back(*chosen);
      labels.push_back(*chosen);
    }

  // Legend, top left: fast and accurate, the corner no configuration reaches.
  const int lx = px0 + 18;
  int ly = py0 + 10;
  for (size_t b = 0; b < backends.size(); ++b) {
    c.disc(float(lx), float(ly + 6), 4.0f, SERIES_COLOURS[b % 3]);
    c.text(lx + 12, ly, backends[b] + " backend", BLACK);
    ly += 18;
  }
  c.ring(float(lx), float(ly + 6), 8.0f, 1.5f, LABEL_GREY);
  c.text(lx + 12, ly, "Pareto front", BLACK);
  c.write_png(path);
}

}  // namespace sdfreel::bench
