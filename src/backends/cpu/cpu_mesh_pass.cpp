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

// Clip space of the pass: its own view, or the plan's camera moved by the sample offset.
glm::mat4 view_projection(const MeshPass& pass, const CpuPassContext& pc) {
  if (pass.view) return pass.view->projection * pass.view->view;
  return sample_projection(pc.camera, pc.offset, pc.frame.width, pc.frame.height) * pc.camera.view;
}

std::vector<ScreenTriangle> setup(const MeshPass& pass, const CpuPassContext& pc,
                                  const glm::ivec2& size) {
  const TriangleMesh& m = *pass.mesh;
  const glm::mat4 view_proj = view_projection(pass, pc);
  std::vector<ScreenTriangle> out;
  for (const MeshInstance& inst : pass.instances) {
    const glm::mat3 normal_matrix(inst.model);
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      ClipVertex v[3];
      for (int k = 0; k < 3; ++k) {
        const unsigned i = m.index(t * 3 + size_t(k));
        const glm::vec3 position(m.positions[i * 3], m.positions[i * 3 + 1],
                                 m.positions[i * 3 + 2]);
        const glm::vec3 normal =
            m.normals.empty()
                ? glm::vec3(0.0f)
                : glm::vec3(m.normals[i * 3], m.normals[i * 3 + 1], m.normals[i * 3 + 2]);
        if (pass.place) {
          const PlacedVertex placed = pass.place(inst, position, normal);
          v[k].world = placed.world;
          v[k].normal = placed.normal;
        } else {
          v[k].world = glm::vec3(inst.model * glm::vec4(position, 1.0f));
          v[k].normal = normal_matrix * normal;
        }
        v[k].clip = view_proj * glm::vec4(v[k].world, 1.0f);
        v[k].uv = m.uvs.empty() ? glm::vec2(0.0f) : glm::vec2(m.uvs[i * 2], m.uvs[i * 2 + 1]);
      }
      ClipVertex clipped[6];
      const int n = clip_near(v, clipped);
      for (int c = 0; c < n; ++c) {
        ScreenTriangle s;
        s.data = inst.data;
        for (int k = 0; k < 3; ++k) {
          const ClipVertex& cv = clipped[c * 3 + k];
          const double w = cv.clip.w;
          s.p[k] = glm::dvec2((cv.clip.x / w * 0.5 + 0.5) * size.x,
                              (cv.clip.y / w * 0.5 + 0.5) * size.y);
          s.inv_w[k] = 1.0 / w;
          s.depth[k] = cv.clip.z / w * 0.5 + 0.5;
          s.v[k] = cv;
        }
        const double area = edge(s.p[0], s.p[1], s.p[2]);
        if (area == 0.0) continue;
        s.front = area > 0.0;
        if ((pass.cull == CullMode::Back && !s.front) || (pass.cull == CullMode::Front && s.front))
          continue;
        if (!s.front) {  // order counter-clockwise, so edge tests and the top-left rule are one
                         // case
          std::swap(s.p[1], s.p[2]);
          std::swap(s.inv_w[1], s.inv_w[2]);
          std::swap(s.depth[1], s.depth[2]);
          std::swap(s.v[1], s.v[2]);
        }
        out.push_back(s);
      }
    }
  }
  return out;
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
  for (int wy = int(std::ceil(lo_y)); wy <= int(std::floor(hi_y)); ++wy)
    for (int wx = int(std::ceil(lo_x)); wx <= int(std::floor(hi_x)); ++wx) {
      const glm::dvec2 p(wx + 0.5, wy + 0.5);
      double b[3];
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        const glm::dvec2& a = s.p[(k + 1) % 3];
        const glm::dvec2& c = s.p[(k + 2) % 3];
        b[k] = edge(a, c, p);
        inside = b[k] > 0.0 || (b[k] == 0.0 && top_left(a, c));
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

// The triangles whose pixel bounds may touch each tile, in mesh order (so each pixel still sees
// its fragments in the same order): a pass of many triangles (fur shells) then costs each tile only
// its own triangles. The bounds are conservative; rasterise() clips exactly.
std::vector<std::vector<unsigned>> bin_by_tile(const std::vector<ScreenTriangle>& triangles,
                                               const glm::ivec2& size, int tile_size) {
  const int width = size.x, height = size.y;
  const int cols = (width + tile_size - 1) / tile_size;
  const int rows = (height + tile_size - 1) / tile_size;
  std::vector<std::vector<unsigned>> bins(size_t(cols * rows));
  for (size_t i = 0; i < triangles.size(); ++i) {
    const glm::dvec2* p = triangles[i].p;
    // Window rows run up, image rows down: image row y = height - 1 - window row.
    const double lo_x = std::min({p[0].x, p[1].x, p[2].x}) - 1.0;
    const double hi_x = std::max({p[0].x, p[1].x, p[2].x}) + 1.0;
    const double lo_y = height - 1 - (std::max({p[0].y, p[1].y, p[2].y}) + 1.0);
    const double hi_y = height - 1 - (std::min({p[0].y, p[1].y, p[2].y}) - 1.0);
    if (hi_x < 0.0 || lo_x >= width || hi_y < 0.0 || lo_y >= height) continue;
    const int c0 = int(std::max(lo_x, 0.0)) / tile_size;
    const int c1 = std::min(cols - 1, int(std::min(hi_x, double(width - 1))) / tile_size);
    const int r0 = int(std::max(lo_y, 0.0)) / tile_size;
    const int r1 = std::min(rows - 1, int(std::min(hi_y, double(height - 1))) / tile_size);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) bins[size_t(r * cols + c)].push_back(unsigned(i));
  }
  return bins;
}

}  // namespace

void run_mesh_pass(const MeshPass& pass, const CpuPassContext& pc, CpuTargets& targets) {
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
  const std::vector<ScreenTriangle> triangles = setup(pass, pc, size);
  const std::vector<std::vector<unsigned>> bins = bin_by_tile(triangles, size, pc.tile_size);
  for_each_tile(size.x, size.y, pc.tile_size, pc.threads, [&](const Tile& t) {
    for (unsigned i : bins[size_t(t.index)]) rasterise(triangles[i], pass, t, size.y, out);
  });
}

}  // namespace sdfreel
