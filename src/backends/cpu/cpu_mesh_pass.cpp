#include "backends/cpu/cpu_mesh_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "render/tiling.h"

namespace sdfreel {

namespace {

// A vertex after the vertex stage: clip position and the varyings.
struct ClipVertex {
  glm::vec4 clip;
  glm::vec3 world, normal;
  glm::vec2 uv;
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t) {
  return {a.clip + (b.clip - a.clip) * t, a.world + (b.world - a.world) * t,
          a.normal + (b.normal - a.normal) * t, a.uv + (b.uv - a.uv) * t};
}

// A triangle ready to rasterise: window positions, 1/w, z_w, and what fragments need.
struct ScreenTriangle {
  glm::dvec2 p[3];  // window coordinates, y up, pixel centres at +0.5
  double inv_w[3];
  double depth[3];  // z_w
  ClipVertex v[3];
  glm::vec4 data;
  bool front;
};

// Clips a triangle against the near plane (z >= -w): 0, 1 or 2 triangles.
int clip_near(const ClipVertex in[3], ClipVertex out[6]) {
  ClipVertex poly[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % 3];
    const float da = a.clip.z + a.clip.w, db = b.clip.z + b.clip.w;
    if (da >= 0.0f) poly[n++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) poly[n++] = lerp(a, b, da / (da - db));
  }
  if (n < 3) return 0;
  out[0] = poly[0], out[1] = poly[1], out[2] = poly[2];
  if (n == 3) return 1;
  out[3] = poly[0], out[4] = poly[2], out[5] = poly[3];
  return 2;
}

// The top-left rule in window space with y up: a pixel centre exactly on an edge is inside when
// the edge is a left edge or a top edge of the (counter-clockwise ordered) triangle.
bool top_left(const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 e = b - a;
  return (e.y == 0.0 && e.x < 0.0) || e.y < 0.0;
}

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The triangle's pixel bounds, with a pixel of margin (conservative; rasterise() clips exactly),
// in image rows (window rows run up, image rows down: image row y = height - 1 - window row).
struct PixelBounds {
  double lo_x, hi_x, lo_y, hi_y;
  bool off_frame(int width, int height) const {
    return hi_x < 0.0 || lo_x >= width || hi_y < 0.0 || lo_y >= height;
  }
};

PixelBounds pixel_bounds(const glm::dvec2 p[3], int height) {
  return {std::min({p[0].x, p[1].x, p[2].x}) - 1.0, std::max({p[0].x, p[1].x, p[2].x}) + 1.0,
          height - 1 - (std::max({p[0].y, p[1].y, p[2].y}) + 1.0),
          height - 1 - (std::min({p[0].y, p[1].y, p[2].y}) - 1.0)};
}

// A vertex's window position, 1 / w and window depth z_w: the window transform of its clip
// position, in double.
struct WindowVertex {
  glm::dvec2 p;
  double inv_w, depth;
};

WindowVertex to_window(const glm::vec4& clip, int width, int height) {
  const double w = clip.w;
  return {glm::dvec2((clip.x / w * 0.5 + 0.5) * width, (clip.y / w * 0.5 + 0.5) * height), 1.0 / w,
          clip.z / w * 0.5 + 0.5};
}

}  // namespace

struct MeshPassCache::Data {
  const MeshPass* placed_for = nullptr;   // the pass whose vertices world and normal hold
  std::vector<glm::vec3> world, normal;   // instance-major: instance * vertex_count + vertex
  std::vector<glm::vec4> clip;            // this sample's clip positions, same order
  std::vector<WindowVertex> window;       // and their window transforms
  std::vector<ScreenTriangle> triangles;  // this sample's, reused
  std::vector<std::vector<unsigned>> bins;
};

MeshPassCache::MeshPassCache() : data_(std::make_unique<Data>()) {}
MeshPassCache::~MeshPassCache() = default;
MeshPassCache::MeshPassCache(MeshPassCache&&) noexcept = default;

namespace {

// The vertex stage: every vertex of every instance placed in world space, once per frame.
void place_vertices(const MeshPass& pass, MeshPassCache::Data& d) {
  const TriangleMesh& m = *pass.mesh;
  const size_t nv = m.vertex_count();
  d.world.resize(pass.instances.size() * nv);
  d.normal.resize(d.world.size());
  size_t o = 0;
  for (const MeshInstance& inst : pass.instances) {
    const glm::mat3 normal_matrix(inst.model);
    for (size_t i = 0; i < nv; ++i, ++o) {
      const glm::vec3 position(m.positions[i * 3], m.positions[i * 3 + 1], m.positions[i * 3 + 2]);
      const glm::vec3 normal = m.normals.empty() ? glm::vec3(0.0f)
                                                 : glm::vec3(m.normals[i * 3], m.normals[i * 3 + 1],
                                                             m.normals[i * 3 + 2]);
      if (pass.place) {
        const PlacedVertex placed = pass.place(inst, position, normal);
        d.world[o] = placed.world;
        d.normal[o] = placed.normal;
      } else {
        d.world[o] = glm::vec3(inst.model * glm::vec4(position, 1.0f));
        d.normal[o] = normal_matrix * normal;
      }
    }
  }
  d.placed_for = &pass;
}

// Clip space of the pass: its own view, or the plan's camera moved by the sample offset.
glm::mat4 view_projection(const MeshPass& pass, const CpuPassContext& pc) {
  if (pass.view) return pass.view->projection * pass.view->view;
  return sample_projection(pc.camera, pc.offset, pc.frame.width, pc.frame.height) * pc.camera.view;
}

// Appends the triangle of window vertices wv and varyings cv() unless it has no area, is culled
// or lies wholly off the frame (the bins would never hold it); cv is called only for triangles
// kept, so culled ones cost no copies.
template <class Varyings>
void emit(const WindowVertex wv[3], Varyings cv, const glm::vec4& data, CullMode cull,
          const glm::ivec2& size, std::vector<ScreenTriangle>& out) {
  const glm::dvec2 p[3] = {wv[0].p, wv[1].p, wv[2].p};
  const double area = edge(p[0], p[1], p[2]);
  if (area == 0.0) return;
  const bool front = area > 0.0;
  if ((cull == CullMode::Back && !front) || (cull == CullMode::Front && front)) return;
  if (pixel_bounds(p, size.y).off_frame(size.x, size.y)) return;
  ScreenTriangle& s = out.emplace_back();
  s.data = data;
  s.front = front;
  // Counter-clockwise order, so edge tests and the top-left rule are one case.
  const int order[3] = {0, front ? 1 : 2, front ? 2 : 1};
  for (int k = 0; k < 3; ++k) {
    const WindowVertex& w = wv[order[k]];
    s.p[k] = w.p;
    s.inv_w[k] = w.inv_w;
    s.depth[k] = w.depth;
    s.v[k] = cv(order[k]);
  }
}

// This sample's screen triangles on a target of `size` into d.triangles: clip positions and window
// transforms once per vertex, then per triangle near clipping (only for triangles that cross the
// near plane: one wholly in front is its own clipped self), culling and the off-frame test.
void setup(const MeshPass& pass, const CpuPassContext& pc, const glm::ivec2& size,
           MeshPassCache::Data& d) {
  const TriangleMesh& m = *pass.mesh;
  if (d.placed_for != &pass) place_vertices(pass, d);
  const glm::mat4 view_proj = view_projection(pass, pc);
  d.clip.resize(d.world.size());
  d.window.resize(d.world.size());
  for (size_t i = 0; i < d.world.size(); ++i) {
    d.clip[i] = view_proj * glm::vec4(d.world[i], 1.0f);
    d.window[i] = to_window(d.clip[i], size.x, size.y);
  }
  d.triangles.clear();
  const size_t nv = m.vertex_count();
  auto uv_of = [&m](unsigned i) {
    return m.uvs.empty() ? glm::vec2(0.0f) : glm::vec2(m.uvs[i * 2], m.uvs[i * 2 + 1]);
  };
  for (size_t n_inst = 0; n_inst < pass.instances.size(); ++n_inst) {
    const glm::vec4& data = pass.instances[n_inst].data;
    const size_t base = n_inst * nv;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      unsigned idx[3];
      bool in_front = true;
      for (int k = 0; k < 3; ++k) {
        idx[k] = m.index(t * 3 + size_t(k));
        const glm::vec4& c = d.clip[base + idx[k]];
        in_front = in_front && c.z + c.w >= 0.0f;
      }
      auto vertex = [&](int k) {
        const size_t o = base + idx[k];
        return ClipVertex{d.clip[o], d.world[o], d.normal[o], uv_of(idx[k])};
      };
      if (in_front) {
        const WindowVertex wv[3] = {d.window[base + idx[0]], d.window[base + idx[1]],
                                    d.window[base + idx[2]]};
        emit(wv, vertex, data, pass.cull, size, d.triangles);
        continue;
      }
      const ClipVertex v[3] = {vertex(0), vertex(1), vertex(2)};
      ClipVertex clipped[6];
      const int n = clip_near(v, clipped);
      for (int c = 0; c < n; ++c) {
        const ClipVertex* cv = clipped + c * 3;
        const WindowVertex wv[3] = {to_window(cv[0].clip, size.x, size.y),
                                    to_window(cv[1].clip, size.x, size.y),
                                    to_window(cv[2].clip, size.x, size.y)};
        emit(
            wv, [cv](int k) { return cv[k]; }, data, pass.cull, size, d.triangles);
      }
    }
  }
}

struct MeshTargets {
  ImageRGBA* colour;  // null: depth only
  ImageRGBA* depth;   // null: none
  bool test, write_depth;
  const ImageInputs* inputs;
};

void rasterise(const ScreenTriangle& s, const MeshPass& pass, const Tile& t, int height,
               const MeshTargets& out) {
  // The tile in window coordinates (rows flipped: image row y is window row height - 1 - y).
  const double lo_x = std::max(double(t.x0), std::min({s.p[0].x, s.p[1].x, s.p[2].x}) - 0.5);
  const double hi_x = std::min(double(t.x1 - 1), std::max({s.p[0].x, s.p[1].x, s.p[2].x}) - 0.5);
  const double lo_y =
      std::max(double(height - t.y1), std::min({s.p[0].y, s.p[1].y, s.p[2].y}) - 0.5);
  const double hi_y =
      std::min(double(height - 1 - t.y0), std::max({s.p[0].y, s.p[1].y, s.p[2].y}) - 0.5);
  const double area = edge(s.p[0], s.p[1], s.p[2]);
  // Edge k runs from vertex k + 1 to k + 2; edge(a, c, p) = ex * (p.y - a.y) - ey * (p.x - a.x)
  // with its per-triangle and per-row parts computed once: the same operations on the same values.
  double ax[3], ay[3], ex[3], ey[3], row[3];
  bool tl[3];
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2& a = s.p[(k + 1) % 3];
    const glm::dvec2& c = s.p[(k + 2) % 3];
    ax[k] = a.x, ay[k] = a.y, ex[k] = c.x - a.x, ey[k] = c.y - a.y;
    tl[k] = top_left(a, c);
  }
  for (int wy = int(std::ceil(lo_y)); wy <= int(std::floor(hi_y)); ++wy) {
    const double centre_y = wy + 0.5;
    for (int k = 0; k < 3; ++k) row[k] = ex[k] * (centre_y - ay[k]);
    for (int wx = int(std::ceil(lo_x)); wx <= int(std::floor(hi_x)); ++wx) {
      const double centre_x = wx + 0.5;
      double b[3];
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        b[k] = row[k] - ey[k] * (centre_x - ax[k]);
        inside = b[k] > 0.0 || (b[k] == 0.0 && tl[k]);
      }
      if (!inside) continue;
      const double l0 = b[0] / area, l1 = b[1] / area, l2 = b[2] / area;
      float z = float(l0 * s.depth[0] + l1 * s.depth[1] + l2 * s.depth[2]);
      if (z < 0.0f || z > 1.0f) continue;  // outside the near/far range, as GL clips
      const int x = wx, y = height - 1 - wy;
      const bool late = bool(pass.shade_depth);
      if (!late && out.depth && out.test && !(z < out.depth->at(x, y)[0])) continue;
      if (!late && !pass.shade) {  // depth only, nothing to discard
        if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
        continue;
      }
      // Perspective-correct varyings.
      const double q0 = l0 * s.inv_w[0], q1 = l1 * s.inv_w[1], q2 = l2 * s.inv_w[2];
      const double qs = q0 + q1 + q2;
      const float w0 = float(q0 / qs), w1 = float(q1 / qs), w2 = float(q2 / qs);
      MeshFragment frag;
      frag.world_position = s.v[0].world * w0 + s.v[1].world * w1 + s.v[2].world * w2;
      frag.world_normal = s.v[0].normal * w0 + s.v[1].normal * w1 + s.v[2].normal * w2;
      frag.uv = s.v[0].uv * w0 + s.v[1].uv * w1 + s.v[2].uv * w2;
      frag.instance_data = s.data;
      frag.front_facing = s.front;
      frag.inputs = out.inputs;
      glm::vec4 c;
      if (late) {
        if (!pass.shade_depth(frag, c, z)) continue;
        if (out.depth && out.test && !(z < out.depth->at(x, y)[0])) continue;
      } else {
        c = pass.shade(frag);
      }
      if (c.a < pass.alpha_cutoff) continue;
      if (out.depth && out.write_depth) out.depth->at(x, y)[0] = z;
      if (!out.colour) continue;
      float* px = out.colour->at(x, y);
      px[0] = c.r;
      px[1] = c.g;
      px[2] = c.b;
      px[3] = c.a;
    }
  }
}

// The triangles whose pixel bounds may touch each tile, in mesh order (so each pixel still sees
// its fragments in the same order): a pass of many triangles (fur shells) then costs each tile only
// its own triangles. The bounds are conservative; rasterise() clips exactly.
void bin_by_tile(const std::vector<ScreenTriangle>& triangles, const glm::ivec2& size,
                 int tile_size, std::vector<std::vector<unsigned>>& bins) {
  const int width = size.x, height = size.y;
  const int cols = (width + tile_size - 1) / tile_size;
  const int rows = (height + tile_size - 1) / tile_size;
  bins.resize(size_t(cols * rows));
  for (std::vector<unsigned>& b : bins) b.clear();
  for (size_t i = 0; i < triangles.size(); ++i) {
    const PixelBounds b = pixel_bounds(triangles[i].p, height);
    if (b.off_frame(width, height)) continue;
    const int c0 = int(std::max(b.lo_x, 0.0)) / tile_size;
    const int c1 = std::min(cols - 1, int(std::min(b.hi_x, double(width - 1))) / tile_size);
    const int r0 = int(std::max(b.lo_y, 0.0)) / tile_size;
    const int r1 = std::min(rows - 1, int(std::min(b.hi_y, double(height - 1))) / tile_size);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) bins[size_t(r * cols + c)].push_back(unsigned(i));
  }
}

}  // namespace

void run_mesh_pass(const MeshPass& pass, const CpuPassContext& pc, CpuTargets& targets,
                   MeshPassCache& cache) {
  if (!pass.mesh) throw std::runtime_error("mesh pass '" + pass.name + "' has no mesh");
  if (!pass.shade && !pass.shade_depth && !pass.colour.empty())
    throw std::runtime_error("mesh pass '" + pass.name + "' has no CPU code");
  MeshTargets out{pass.colour.empty() ? nullptr : &targets.get(pass.colour, pass.name), nullptr,
                  false, false, nullptr};
  if (!pass.depth.empty()) {
    out.depth = &targets.get(pass.depth, pass.name);
    out.test = pass.depth_test != DepthTest::Off;
    out.write_depth = pass.depth_test != DepthTest::TestOnly;
  }
  if (!out.colour && !out.depth)
    throw std::runtime_error("mesh pass '" + pass.name + "' writes no target");
  ImageInputs inputs;
  for (const ImageInput& in : pass.inputs) {
    if (in.target == pass.colour || in.target == pass.depth)
      throw std::runtime_error("mesh pass '" + pass.name + "' reads its own target '" + in.target +
                               "'");
    inputs.images.push_back(&targets.get(in.target, pass.name));
  }
  out.inputs = &inputs;
  const ImageRGBA& drawn = out.colour ? *out.colour : *out.depth;
  if (out.colour && out.depth &&
      (out.depth->width != drawn.width || out.depth->height != drawn.height))
    throw std::runtime_error("mesh pass '" + pass.name + "': colour and depth sizes differ");
  const glm::ivec2 size(drawn.width, drawn.height);
  MeshPassCache::Data& d = cache.data();
  setup(pass, pc, size, d);
  bin_by_tile(d.triangles, size, pc.tile_size, d.bins);
  for_each_tile(size.x, size.y, pc.tile_size, pc.threads, [&](const Tile& t) {
    for (unsigned i : d.bins[size_t(t.index)]) rasterise(d.triangles[i], pass, t, size.y, out);
  });
}

}  // namespace sdfreel
