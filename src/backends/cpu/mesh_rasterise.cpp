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
    edges.tl[k] = top_left(a, c) ? -1 : 0;
  }
  const bool late = bool(pass.shade_depth);
  const bool in_lanes = !late && bool(pass.shade8);
  MeshFragment frag;  // the triangle's constants; each fragment fills in its varyings
  frag.instance_data = pass.instances[s.instance].data;
  frag.front_facing = s.front;
  frag.inputs = out.inputs;
  const unsigned i0 = s.v[0], i1 = s.v[1], i2 = s.v[2];
  const double depth[3] = {wv[0]->depth, wv[1]->depth, wv[2]->depth};
  auto write = [&](int x, int y, float z, const glm::vec4& c) {
    if (c.a < pass.alpha_cutoff) return;
    if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
    if (!out.colour) return;
    float* px = out.colour->at(x, y);
    px[0] = c.r;
    px[1] = c.g;
    px[2] = c.b;
    px[3] = c.a;
  };
  // The lanes' path (MeshPass::shade8): fragments that passed the early tests wait until eight
  // are there or the triangle ends. A triangle covers each pixel once, so deferring its writes
  // changes no test.
  struct Waiting {
    int x, y;
    float z, w[3];
  };
  Waiting waiting[LANES];
  int count = 0;
  auto flush = [&] {
    if (count == 0) return;
    float weights[3][LANES];
    for (int k = 0; k < LANES; ++k)
      for (int j = 0; j < 3; ++j) weights[j][k] = waiting[k < count ? k : 0].w[j];
    const F8 w[3] = {load8(weights[0]), load8(weights[1]), load8(weights[2])};
    MeshFragments8 f8;
    f8.world_position = d.world[i0] * w[0] + d.world[i1] * w[1] + d.world[i2] * w[2];
    f8.world_normal = d.normal[i0] * w[0] + d.normal[i1] * w[1] + d.normal[i2] * w[2];
    f8.uv = {d.uv[i0].x * w[0] + d.uv[i1].x * w[1] + d.uv[i2].x * w[2],
             d.uv[i0].y * w[0] + d.uv[i1].y * w[1] + d.uv[i2].y * w[2]};
    f8.instance_data = frag.instance_data;
    f8.front_facing = frag.front_facing;
    f8.inputs = frag.inputs;
    f8.count = count;
    FragmentColours8 c{};
    pass.shade8(f8, c);
    for (int k = 0; k < count; ++k)
      write(waiting[k].x, waiting[k].y, waiting[k].z, glm::vec4(c.r[k], c.g[k], c.b[k], c.a[k]));
    count = 0;
  };
  // The depth and varying weights of a span's four pixels from their edge values, each lane the
  // scalar operations of one pixel: barycentrics l_k = b_k / area, depth sum_k l_k depth_k,
  // q_k = l_k / w_k and weights q_k / (q_0 + q_1 + q_2). Lanes outside the triangle are ignored.
  const double inv_w[3] = {wv[0]->inv_w, wv[1]->inv_w, wv[2]->inv_w};
  struct SpanWeights {
    float z[SPAN], w[3][SPAN];
  };
  auto span_weights = [&](const EdgeSpan& e, SpanWeights& out_w) {
    const D4 l[3] = {e.b[0] / area, e.b[1] / area, e.b[2] / area};
    const D4 z = l[0] * depth[0] + l[1] * depth[1] + l[2] * depth[2];
    const D4 q[3] = {l[0] * inv_w[0], l[1] * inv_w[1], l[2] * inv_w[2]};
    const D4 sum = q[0] + q[1] + q[2];
    for (int j = 0; j < SPAN; ++j) out_w.z[j] = float(z[j]);
    for (int k = 0; k < 3; ++k) {
      const D4 w = q[k] / sum;
      for (int j = 0; j < SPAN; ++j) out_w.w[k][j] = float(w[j]);
    }
  };
  // One covered pixel.
  auto fragment = [&](int x, int y, float z, float w0, float w1, float w2) {
    if (z < 0.0f || z > 1.0f) return;  // outside the near/far range, as GL clips
    if (!late && out.depth && out.test && !(z < out.depth->at(x, y)[0])) return;
    if (!late && !pass.shade) {  // depth only, nothing to discard
      if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
      return;
    }
    if (in_lanes) {
      waiting[count++] = {x, y, z, {w0, w1, w2}};
      if (count == LANES) flush();
      return;
    }
    frag.world_position = d.world[i0] * w0 + d.world[i1] * w1 + d.world[i2] * w2;
    frag.world_normal = d.normal[i0] * w0 + d.normal[i1] * w1 + d.normal[i2] * w2;
    frag.uv = d.uv[i0] * w0 + d.uv[i1] * w1 + d.uv[i2] * w2;
    glm::vec4 c;
    if (late) {
      if (!pass.shade_depth(frag, c, z)) return;
      if (out.depth && out.test && !(z < out.depth->at(x, y)[0])) return;
    } else {
      c = pass.shade(frag);
    }
    write(x, y, z, c);
  };
  for (int wy = y_lo; wy <= y_hi; ++wy) {
    edges.start_row(wy);
    const int y = height - 1 - wy;
    for (int wx = x_lo; wx <= x_hi; wx += SPAN) {
      EdgeSpan span;
      unsigned bits = edges.cover(wx, x_hi, span);
      if (bits == 0) continue;
      SpanWeights sw;
      span_weights(span, sw);
      for (; bits != 0; bits &= bits - 1) {
        const int j = __builtin_ctz(bits);
        fragment(wx + j, y, sw.z[j], sw.w[0][j], sw.w[1][j], sw.w[2][j]);
      }
    }
  }
  flush();
}

}  // namespace sdfreel
