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
  MeshFragment frag;  // the triangle's constants; each fragment fills in its varyings
  frag.instance_data = pass.instances[s.instance].data;
  frag.front_facing = s.front;
  frag.inputs = out.inputs;
  const unsigned i0 = s.v[0], i1 = s.v[1], i2 = s.v[2];
  const D4 inv_w = {wv[0]->inv_w, wv[1]->inv_w, wv[2]->inv_w, 0.0};
  const double depth[3] = {wv[0]->depth, wv[1]->depth, wv[2]->depth};
  // One covered pixel with its edge values (lanes 0-2; lane 3 is unused): the barycentric weights
  // l_k = b_k / area, q_k = l_k / w_k and w_k = q_k / (q_0 + q_1 + q_2), each lane exactly the
  // scalar operation (IEEE division), so the same bits with one division instruction for three.
  auto fragment = [&](int x, int y, const D4& bv) {
    const D4 l = bv / area;
    float z = float(l[0] * depth[0] + l[1] * depth[1] + l[2] * depth[2]);
    if (z < 0.0f || z > 1.0f) return;  // outside the near/far range, as GL clips
    if (!late && out.depth && out.test && !(z < out.depth->at(x, y)[0])) return;
    if (!late && !pass.shade) {  // depth only, nothing to discard
      if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
      return;
    }
    // Perspective-correct varyings.
    const D4 q = l * inv_w;
    const D4 wd = q / (q[0] + q[1] + q[2]);
    const float w0 = float(wd[0]), w1 = float(wd[1]), w2 = float(wd[2]);
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
      for (unsigned bits = edges.cover(wx, x_hi, span); bits != 0; bits &= bits - 1) {
        const int j = __builtin_ctz(bits);
        fragment(wx + j, y, D4{span.b[0][j], span.b[1][j], span.b[2][j], 0.0});
      }
    }
  }
}

}  // namespace sdfreel
