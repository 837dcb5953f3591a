#include "backends/cpu/mesh_rasterise.h"

#include <algorithm>

#include "backends/cpu/covered_pixels.h"
#include "backends/cpu/mesh_setup.h"

namespace sdfreel {

namespace {

// The top-left rule in window space with y up: a pixel centre exactly on an edge is inside when
// the edge is a left edge or a top edge of the (counter-clockwise ordered) triangle.
bool top_left(const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 e = b - a;
  return (e.y == 0.0 && e.x < 0.0) || e.y < 0.0;
}

const M8 LANE_INDEX = {0, 1, 2, 3, 4, 5, 6, 7};

}  // namespace

void rasterise(const RasterTriangle& s, const VertexArrays& d, const MeshPass& pass, const Tile& t,
               int height, const MeshTargets& out) {
  // The triangle's pixels within the tile, in window coordinates (image row y is window row
  // height - 1 - y).
  const int x_lo = std::max(s.x0, t.x0), x_hi = std::min(s.x1, t.x1 - 1);
  const int y_lo = std::max(s.y0, height - t.y1), y_hi = std::min(s.y1, height - 1 - t.y0);
  const int width = (out.colour ? out.colour : out.depth)->width;  // the same for both
  const WindowVertex* wv[3] = {&d.window[s.v[0]], &d.window[s.v[1]], &d.window[s.v[2]]};
  // Edge k runs from vertex k + 1 to k + 2; edge(a, c, p) = ex * (p.y - a.y) - ey * (p.x - a.x)
  // with its per-triangle and per-row parts computed once: the same operations on the same values.
  EdgeRow edges;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2& a = wv[(k + 1) % 3]->p;
    const glm::dvec2& c = wv[(k + 2) % 3]->p;
    edges.set_edge(k, a.x, a.y, c.x, c.y, top_left(a, c));
  }
  // Rows of one or two spans gain nothing from narrowing.
  const bool narrow = x_hi - x_lo < 2 * SPAN;
  const bool late = bool(pass.shade_depth);
  const bool in_lanes = !late && pass.shade && pass.shade8;
  MeshFragment frag;  // the triangle's constants; each fragment fills in its varyings
  frag.instance_data = pass.instances[s.instance].data;
  frag.front_facing = s.front;
  frag.inputs = out.inputs;
  const unsigned i0 = s.v[0], i1 = s.v[1], i2 = s.v[2];
  // Pixel i of the image in the depth and colour targets (run_mesh_pass checked their sizes).
  auto depth_at = [&](int i) -> float& { return out.depth->pixels[size_t(i) * 4]; };
  auto colour_at = [&](int i) { return &out.colour->pixels[size_t(i) * 4]; };
  // A fragment that passed every test, alpha's included.
  auto put = [&](int i, float z, float r, float g, float b, float a) {
    if (out.depth && out.write_depth) depth_at(i) = z;
    if (!out.colour) return;
    float* px = colour_at(i);
    px[0] = r;
    px[1] = g;
    px[2] = b;
    px[3] = a;
  };
  auto write = [&](int i, float z, const glm::vec4& c) {
    if (c.a < pass.alpha_cutoff) return;
    put(i, z, c.r, c.g, c.b, c.a);
  };
  // One covered pixel, one at a time.
  auto fragment = [&](int i, float z, float w0, float w1, float w2) {
    if (z < 0.0f || z > 1.0f) return;  // outside the near/far range, as GL clips
    if (!late && out.depth && out.test && !(z < depth_at(i))) return;
    if (!late && !pass.shade) {  // depth only, nothing to discard
      if (out.depth && out.write_depth) depth_at(i) = z;
      return;
    }
    frag.world_position = d.world[i0] * w0 + d.world[i1] * w1 + d.world[i2] * w2;
    frag.world_normal = d.normal[i0] * w0 + d.normal[i1] * w1 + d.normal[i2] * w2;
    frag.uv = d.uv[i0] * w0 + d.uv[i1] * w1 + d.uv[i2] * w2;
    glm::vec4 c;
    if (late) {
      if (!pass.shade_depth(frag, c, z)) return;
      if (out.depth && out.test && !(z < depth_at(i))) return;
    } else {
      c = pass.shade(frag);
    }
    write(i, z, c);
  };
  CoveredPixels pixels;
  // The lanes' path (MeshPass::shade8): pixels i .. i + n - 1 of the chunk, the same tests and
  // writes as fragment() and write() in lanes. A triangle covers each pixel once, so testing a
  // group before writing any of it changes no test.
  auto group = [&](int i, int n) {
    const M8 used = LANE_INDEX < n;
    const F8 z = load8(pixels.z + i);
    M8 keep = used & ~((z < 0.0f) | (z > 1.0f));  // outside the near/far range, as GL clips
    if (out.depth && out.test) {
      F8 stored;
      for (int k = 0; k < LANES; ++k) stored[k] = depth_at(pixels.at[i + k]);
      keep &= z < stored;
    }
    if (!any(keep)) return;
    F8 w[3];
    for (int j = 0; j < 3; ++j) {
      const F8 v = load8(pixels.w[j] + i);
      w[j] = select(used, v, splat(v[0]));
    }
    MeshFragments8 f8;
    f8.world_position = d.world[i0] * w[0] + d.world[i1] * w[1] + d.world[i2] * w[2];
    f8.world_normal = d.normal[i0] * w[0] + d.normal[i1] * w[1] + d.normal[i2] * w[2];
    f8.uv = {d.uv[i0].x * w[0] + d.uv[i1].x * w[1] + d.uv[i2].x * w[2],
             d.uv[i0].y * w[0] + d.uv[i1].y * w[1] + d.uv[i2].y * w[2]};
    f8.instance_data = frag.instance_data;
    f8.front_facing = frag.front_facing;
    f8.inputs = frag.inputs;
    f8.count = n;
    FragmentColours8 c;  // zeros by assignment: c{} is a rep stos, slow to start
    c.r = c.g = c.b = c.a = splat(0.0f);
    pass.shade8(f8, c);
    for (unsigned bits = lane_bits(keep & ~(c.a < pass.alpha_cutoff)); bits != 0;
         bits &= bits - 1) {
      const int k = __builtin_ctz(bits);
      put(pixels.at[i + k], z[k], c.r[k], c.g[k], c.b[k], c.a[k]);
    }
  };
  // The covered pixels in chunks: packed row by row, then weighed and drawn in that order.
  const TriangleWeights weights{s.area,
                                {wv[0]->depth, wv[1]->depth, wv[2]->depth},
                                {wv[0]->inv_w, wv[1]->inv_w, wv[2]->inv_w}};
  auto draw = [&] {
    pixels.weigh(weights);
    if (in_lanes)
      for (int i = 0; i < pixels.count; i += LANES) group(i, std::min(LANES, pixels.count - i));
    else
      for (int i = 0; i < pixels.count; ++i)
        fragment(pixels.at[i], pixels.z[i], pixels.w[0][i], pixels.w[1][i], pixels.w[2][i]);
    pixels.count = 0;
  };
  for (int wy = y_lo; wy <= y_hi; ++wy) {
    edges.start_row(wy);
    int first = x_lo, last = x_hi;
    if (!narrow && !edges.columns(first, last)) continue;
    const int row_start = (height - 1 - wy) * width;
    for (int wx = first; wx <= last; wx += SPAN) {
      if (pixels.full()) draw();
      EdgeSpan span;
      pixels.append(span, edges.cover(wx, last, span), row_start + wx);
    }
  }
  draw();
}

}  // namespace sdfreel
