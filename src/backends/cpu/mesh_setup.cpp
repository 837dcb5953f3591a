#include "backends/cpu/mesh_setup.h"

#include <algorithm>
#include <cmath>

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

// Appends triangle idx (indices into d's vertex arrays) unless it has no area, is culled or covers
// no pixel centre of the frame.
void emit(const unsigned idx[3], unsigned instance, CullMode cull, const glm::ivec2& size,
          MeshPassCache::Data& d) {
  const WindowVertex* w = d.window.data();
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
  t.area = edge(p[order[0]], p[order[1]], p[order[2]]);
  t.front = front;
  d.triangles.push_back(t);
}

// Appends a near-clipped corner to the vertex arrays; returns its index.
unsigned add_clipped(const ClipVertex& c, const glm::ivec2& size, MeshPassCache::Data& d) {
  d.world.push_back(c.world);
  d.normal.push_back(c.normal);
  d.uv.push_back(c.uv);
  d.window.push_back(to_window(c.clip, size.x, size.y));
  return unsigned(d.window.size() - 1);
}

}  // namespace

bool centre_range(double lo, double hi, int n, int& first, int& last) {
  const double a = std::ceil(lo - 0.5), b = std::floor(hi - 0.5);
  if (!(a <= b) || !(b >= 0.0) || !(a <= double(n - 1))) return false;
  first = a > 0.0 ? int(a) : 0;
  last = b < double(n - 1) ? int(b) : n - 1;
  return true;
}

void place_vertices(const MeshPass& pass, MeshPassCache::Data& d) {
  if (d.placed_for == &pass) return;
  const TriangleMesh& m = *pass.mesh;
  const size_t nv = m.vertex_count();
  d.placed = pass.instances.size() * nv;
  d.world.resize(d.placed);
  d.normal.resize(d.placed);
  d.uv.resize(d.placed);
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
      d.uv[o] = m.uvs.empty() ? glm::vec2(0.0f) : glm::vec2(m.uvs[i * 2], m.uvs[i * 2 + 1]);
    }
  }
  d.placed_for = &pass;
}

void setup_triangles(const MeshPass& pass, const glm::mat4& view_proj, const glm::ivec2& size,
                     MeshPassCache::Data& d) {
  // Drop the previous sample's clipped corners.
  d.world.resize(d.placed);
  d.normal.resize(d.placed);
  d.uv.resize(d.placed);
  d.clip.resize(d.placed);
  d.window.resize(d.placed);
  for (size_t i = 0; i < d.placed; ++i) {
    d.clip[i] = view_proj * glm::vec4(d.world[i], 1.0f);
    d.window[i] = to_window(d.clip[i], size.x, size.y);
  }
  d.triangles.clear();
  const TriangleMesh& m = *pass.mesh;
  const size_t nv = m.vertex_count();
  for (size_t n_inst = 0; n_inst < pass.instances.size(); ++n_inst) {
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
        emit(idx, unsigned(n_inst), pass.cull, size, d);
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
        for (int k = 0; k < 3; ++k) cidx[k] = add_clipped(clipped[c * 3 + k], size, d);
        emit(cidx, unsigned(n_inst), pass.cull, size, d);
      }
    }
  }
}

void bin_by_tile(const MeshPassCache::Data& d, const glm::ivec2& size, int tile_size,
                 std::vector<std::vector<unsigned>>& bins) {
  const int cols = (size.x + tile_size - 1) / tile_size;
  const int rows = (size.y + tile_size - 1) / tile_size;
  bins.resize(size_t(cols * rows));
  for (std::vector<unsigned>& b : bins) b.clear();
  for (size_t i = 0; i < d.triangles.size(); ++i) {
    const RasterTriangle& t = d.triangles[i];
    // Window rows y0..y1 are image rows height - 1 - y1 .. height - 1 - y0.
    const int r0 = (size.y - 1 - t.y1) / tile_size, r1 = (size.y - 1 - t.y0) / tile_size;
    const int c0 = t.x0 / tile_size, c1 = t.x1 / tile_size;
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) bins[size_t(r * cols + c)].push_back(unsigned(i));
  }
}

}  // namespace sdfreel
