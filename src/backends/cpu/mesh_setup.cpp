#include "backends/cpu/mesh_setup.h"

#include <algorithm>
#include <cmath>

#include "backends/cpu/edge_span.h"
#include "render/tiling.h"

namespace sdfreel {

namespace {

// Batches are runs of whole instances with at least this many triangles, so that a pass of many
// instances (fur shells) sets up on every thread and one of a few triangles stays on one.
constexpr size_t MIN_BATCH_TRIANGLES = 4096;

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

// The window transform of a clip position, in double.
WindowVertex to_window(const glm::vec4& clip, int width, int height) {
  const double w = clip.w;
  return {glm::dvec2((clip.x / w * 0.5 + 0.5) * width, (clip.y / w * 0.5 + 0.5) * height), 1.0 / w,
          clip.z / w * 0.5 + 0.5};
}

// to_window of SPAN clip positions at once: the same double operations in each lane, so the same
// bits, with a division instruction for four vertices.
void to_window(const glm::vec4* clip, int width, int height, WindowVertex* out) {
  D4 x, y, z, w;
  for (int j = 0; j < SPAN; ++j)
    x[j] = clip[j].x, y[j] = clip[j].y, z[j] = clip[j].z, w[j] = clip[j].w;
  const D4 px = (x / w * 0.5 + 0.5) * double(width), py = (y / w * 0.5 + 0.5) * double(height);
  const D4 inv_w = 1.0 / w, depth = z / w * 0.5 + 0.5;
  for (int j = 0; j < SPAN; ++j) out[j] = {glm::dvec2(px[j], py[j]), inv_w[j], depth[j]};
}

// Appends triangle idx (indices into window) unless it has no area, is culled or covers no pixel
// centre of the frame.
void emit(const WindowVertex* w, const unsigned idx[3], bool clipped, unsigned instance,
          CullMode cull, const glm::ivec2& size, std::vector<RasterTriangle>& out) {
  const glm::dvec2 p[3] = {w[idx[0]].p, w[idx[1]].p, w[idx[2]].p};
  const double area = edge(p[0], p[1], p[2]);
  if (area == 0.0) return;
  const bool front = area > 0.0;
  if ((cull == CullMode::Back && !front) || (cull == CullMode::Front && front)) return;
  RasterTriangle t;
  if (!centre_range(std::min({p[0].x, p[1].x, p[2].x}), std::max({p[0].x, p[1].x, p[2].x}), size.x,
                    t.x0, t.x1) ||
      !centre_range(std::min({p[0].y, p[1].y, p[2].y}), std::max({p[0].y, p[1].y, p[2].y}), size.y,
                    t.y0, t.y1))
    return;
  const int order[3] = {0, front ? 1 : 2, front ? 2 : 1};
  for (int k = 0; k < 3; ++k) t.v[k] = idx[order[k]];
  t.instance = instance;
  // In counter-clockwise order: the area itself when that is the given order (the same operations
  // on the same values).
  t.area = front ? area : edge(p[order[0]], p[order[1]], p[order[2]]);
  t.front = front;
  t.clipped = clipped;
  out.push_back(t);
}

// Appends a near-clipped corner to the batch's vertices; returns its index there.
unsigned add_clipped(const ClipVertex& c, const glm::ivec2& size, TriangleBatch& b) {
  b.world.push_back(c.world);
  b.normal.push_back(c.normal);
  b.uv.push_back(c.uv);
  b.window.push_back(to_window(c.clip, size.x, size.y));
  return unsigned(b.window.size() - 1);
}

// The triangles whose pixel range touches each tile, in mesh order (so each pixel still sees its
// fragments in the same order whatever the tiling).
void bin_by_tile(const glm::ivec2& size, int tile_size, TriangleBatch& b) {
  const int cols = (size.x + tile_size - 1) / tile_size;
  const int rows = (size.y + tile_size - 1) / tile_size;
  b.bins.resize(size_t(cols * rows));
  for (std::vector<unsigned>& bin : b.bins) bin.clear();
  // Pixel coordinates are not negative: a shift when tiles are a power of two (the default), not
  // four integer divisions per triangle.
  const int shift = __builtin_ctz(unsigned(tile_size));
  const bool pow2 = (tile_size & (tile_size - 1)) == 0;
  auto tile_of = [&](int pixel) { return pow2 ? pixel >> shift : pixel / tile_size; };
  for (size_t i = 0; i < b.triangles.size(); ++i) {
    const RasterTriangle& t = b.triangles[i];
    // Window rows y0..y1 are image rows height - 1 - y1 .. height - 1 - y0.
    const int r0 = tile_of(size.y - 1 - t.y1), r1 = tile_of(size.y - 1 - t.y0);
    const int c0 = tile_of(t.x0), c1 = tile_of(t.x1);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) b.bins[size_t(r * cols + c)].push_back(unsigned(i));
  }
}

// One batch: its vertices' clip positions and window transforms, then its triangles in mesh
// order, near-clipping those that cross the near plane, then its bins.
void setup_batch(const MeshPass& pass, const glm::mat4& view_proj, const glm::ivec2& size,
                 int tile_size, MeshPassCache::Data& d, TriangleBatch& b) {
  const TriangleMesh& m = *pass.mesh;
  const size_t nv = m.vertex_count();
  const size_t first = b.first_instance * nv, end = b.end_instance * nv;
  for (size_t i = first; i < end; ++i) d.clip[i] = view_proj * glm::vec4(d.world[i], 1.0f);
  size_t i = first;
  for (; i + SPAN <= end; i += SPAN) to_window(&d.clip[i], size.x, size.y, &d.window[i]);
  for (; i < end; ++i) d.window[i] = to_window(d.clip[i], size.x, size.y);
  b.triangles.clear();
  b.world.clear(), b.normal.clear(), b.uv.clear(), b.window.clear();
  for (size_t n_inst = b.first_instance; n_inst < b.end_instance; ++n_inst) {
    const unsigned base = unsigned(n_inst * nv);
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      unsigned idx[3];
      bool in_front = true;
      for (int k = 0; k < 3; ++k) {
        idx[k] = base + m.index(t * 3 + size_t(k));
        const glm::vec4& c = d.clip[idx[k]];
        in_front = in_front && c.z + c.w >= 0.0f;
      }
      // A triangle wholly in front of the near plane is its own clipped self.
      if (in_front) {
        emit(d.window.data(), idx, false, unsigned(n_inst), pass.cull, size, b.triangles);
        continue;
      }
      ClipVertex v[3];
      for (int k = 0; k < 3; ++k) {
        const unsigned o = idx[k];
        v[k] = ClipVertex{d.clip[o], d.world[o], d.normal[o], d.uv[o]};
      }
      ClipVertex clipped[6];
      const int n = clip_near(v, clipped);
      for (int c = 0; c < n; ++c) {
        unsigned cidx[3];
        for (int k = 0; k < 3; ++k) cidx[k] = add_clipped(clipped[c * 3 + k], size, b);
        emit(b.window.data(), cidx, true, unsigned(n_inst), pass.cull, size, b.triangles);
      }
    }
  }
  bin_by_tile(size, tile_size, b);
}

}  // namespace

bool centre_range(double lo, double hi, int n, int& first, int& last) {
  const double a = std::ceil(lo - 0.5), b = std::floor(hi - 0.5);
  if (!(a <= b) || !(b >= 0.0) || !(a <= double(n - 1))) return false;
  first = a > 0.0 ? int(a) : 0;
  last = b < double(n - 1) ? int(b) : n - 1;
  return true;
}

void place_vertices(const MeshPass& pass, int threads, MeshPassCache::Data& d) {
  if (d.placed_for == &pass) return;
  const TriangleMesh& m = *pass.mesh;
  const size_t nv = m.vertex_count();
  const size_t placed = pass.instances.size() * nv;
  d.world.resize(placed);
  d.normal.resize(placed);
  d.uv.resize(placed);
  // Each instance's vertices on their own (`place` is a pure function): in parallel.
  for_each_index(pass.instances.size(), threads, [&](size_t n) {
    const MeshInstance& inst = pass.instances[n];
    const glm::mat3 normal_matrix(inst.model);
    for (size_t i = 0, o = n * nv; i < nv; ++i, ++o) {
      const glm::vec3 position(m.positions[i * 3], m.positions[i * 3 + 1], m.positions[i * 3 + 2]);
      const glm::vec3 normal = m.normals.empty() ? glm::vec3(0.0f)
                                                 : glm::vec3(m.normals[i * 3], m.normals[i * 3 + 1],
                                                             m.normals[i * 3 + 2]);
      if (pass.place) {
        const PlacedVertex placed_vertex = pass.place(inst, position, normal);
        d.world[o] = placed_vertex.world;
        d.normal[o] = placed_vertex.normal;
      } else {
        d.world[o] = glm::vec3(inst.model * glm::vec4(position, 1.0f));
        d.normal[o] = normal_matrix * normal;
      }
      d.uv[o] = m.uvs.empty() ? glm::vec2(0.0f) : glm::vec2(m.uvs[i * 2], m.uvs[i * 2 + 1]);
    }
  });
  d.placed_for = &pass;
}

void setup_batches(const MeshPass& pass, const glm::mat4& view_proj, const glm::ivec2& size,
                   int tile_size, int threads, MeshPassCache::Data& d) {
  const size_t instances = pass.instances.size();
  const size_t triangles = instances * pass.mesh->triangle_count();
  const size_t n = std::max<size_t>(1, std::min(instances, triangles / MIN_BATCH_TRIANGLES));
  d.clip.resize(d.world.size());
  d.window.resize(d.world.size());
  d.batches.resize(n);
  for (size_t i = 0; i < n; ++i) {
    d.batches[i].first_instance = instances * i / n;
    d.batches[i].end_instance = instances * (i + 1) / n;
  }
  for_each_index(n, threads,
                 [&](size_t i) { setup_batch(pass, view_proj, size, tile_size, d, d.batches[i]); });
}

}  // namespace sdfreel
