#include "backends/cpu/mesh_rasterise.h"

#include <algorithm>

#include "backends/cpu/edge_span.h"
#include "backends/cpu/mesh_setup.h"

namespace sdfreel {

namespace {

// The top-left rule in window space with y up: a pixel centre exactly on an edge is inside when
// the edge is a left edge or a top edge of the (counter-clockwise ordered) triangle.
bool top_left(const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 e = b - a;
  return (e.y == 0.0 && e.x < 0.0) || e.y < 0.0;
}

// Perspective-correct weights of a span's pixels: q_k = l_k / w_k, w_k = q_k / (q_0 + q_1 + q_2).
struct SpanWeights {
  D4 w[3];
};

SpanWeights perspective_weights(const D4 l[3], const double inv_w[3]) {
  const D4 q0 = l[0] * inv_w[0], q1 = l[1] * inv_w[1], q2 = l[2] * inv_w[2];
  const D4 qs = q0 + q1 + q2;
  return {{q0 / qs, q1 / qs, q2 / qs}};
}

}  // namespace

void rasterise(const RasterTriangle& s, const VertexArrays& d, const MeshPass& pass, const Tile& t,
               int height, const MeshTargets& out) {
  // The triangle's pixels within the tile, in window coordinates (image row y is window row
  // height - 1 - y).
  const int x_lo = std::max(s.x0, t.x0), x_hi = std::min(s.x1, t.x1 - 1);
  const int y_lo = std::max(s.y0, height - t.y1), y_hi = std::min(s.y1, height - 1 - t.y0);
  const WindowVertex* wv[3] = {&d.window[s.v[0]], &d.window[s.v[1]], &d.window[s.v[2]]};
  const double area = s.area;
  // Edge k runs from vertex k + 1 to k + 2; edge(a, c, p) = ex * (p.y - a.y) - ey * (p.x - a.x)
  // with its per-triangle and per-row parts computed once: the same operations on the same values.
  EdgeRow edges;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2& a = wv[(k + 1) % 3]->p;
    const glm::dvec2& c = wv[(k + 2) % 3]->p;
    edges.ax[k] = a.x, edges.ay[k] = a.y, edges.ex[k] = c.x - a.x, edges.ey[k] = c.y - a.y;
    edges.tl[k] = top_left(a, c);
  }
  const bool late = bool(pass.shade_depth);
  const glm::vec4 instance_data = pass.instances[s.instance].data;
  const unsigned i0 = s.v[0], i1 = s.v[1], i2 = s.v[2];
  const double depth[3] = {wv[0]->depth, wv[1]->depth, wv[2]->depth};
  const double inv_w[3] = {wv[0]->inv_w, wv[1]->inv_w, wv[2]->inv_w};
  const bool varyings = late || pass.shade;
  // One covered pixel j of a span: the weights' lanes hold exactly the scalar operations' results
  // (IEEE division, sums in the same order), so every bit is the per-pixel stage's.
  auto fragment = [&](int x, int y, float z, const SpanWeights& sw, int j) {
    if (!late && out.depth && out.test && !(z < out.depth->at(x, y)[0])) return;
    if (!late && !pass.shade) {  // depth only, nothing to discard
      if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
      return;
    }
    const float w0 = float(sw.w[0][j]), w1 = float(sw.w[1][j]), w2 = float(sw.w[2][j]);
    MeshFragment frag;
    frag.world_position = d.world[i0] * w0 + d.world[i1] * w1 + d.world[i2] * w2;
    frag.world_normal = d.normal[i0] * w0 + d.normal[i1] * w1 + d.normal[i2] * w2;
    frag.uv = d.uv[i0] * w0 + d.uv[i1] * w1 + d.uv[i2] * w2;
    frag.instance_data = instance_data;
    frag.front_facing = s.front;
    frag.inputs = out.inputs;
    glm::vec4 c;
    if (late) {
      if (!pass.shade_depth(frag, c, z)) return;
      if (out.depth && out.test && !(z < out.depth->at(x, y)[0])) return;
    } else {
      c = pass.shade(frag);
    }
    if (c.a < pass.alpha_cutoff) return;
    if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
    if (!out.colour) return;
    float* px = out.colour->at(x, y);
    px[0] = c.r;
    px[1] = c.g;
    px[2] = c.b;
    px[3] = c.a;
  };
  for (int wy = y_lo; wy <= y_hi; ++wy) {
    edges.start_row(wy);
    const int y = height - 1 - wy;
    for (int wx = x_lo; wx <= x_hi; wx += SPAN) {
      EdgeSpan span;
      unsigned bits = edges.cover(wx, x_hi, span);
      if (bits == 0) continue;
      // Window depth from the barycentric weights l_k = b_k / area, for the span's pixels at once.
      D4 l[3];
      for (int k = 0; k < 3; ++k) l[k] = span.b[k] / area;
      const D4 zw = l[0] * depth[0] + l[1] * depth[1] + l[2] * depth[2];
      SpanWeights sw;
      if (varyings) sw = perspective_weights(l, inv_w);
      for (; bits != 0; bits &= bits - 1) {
        const int j = __builtin_ctz(bits);
        const float z = float(zw[j]);
        if (z < 0.0f || z > 1.0f) continue;  // outside the near/far range, as GL clips
        fragment(wx + j, y, z, sw, j);
      }
    }
  }
}

}  // namespace sdfreel
