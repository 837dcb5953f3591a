#pragma once
// The CPU mesh pass's rule in its plainest form, for tests: every triangle in mesh order tested at
// every pixel centre of the frame, one pixel at a time, in double (the scalar per-pixel code the
// rasteriser had before it went to tiles, bins and lanes). Same operations on the same values as
// the rasteriser must perform, so its images are the bits run_mesh_pass must give. Handles what
// the tests use: no `place`, `shade` (no shade_depth), a pass view, colour and depth targets.
#include <algorithm>
#include <vector>

#include "render/frame_plan.h"
#include "render/image.h"

namespace sdfreel::test {

struct ReferenceVertex {
  glm::vec4 clip;
  glm::vec3 world, normal;
  glm::vec2 uv;
};

struct ReferenceImages {
  ImageRGBA colour, depth;
  std::vector<int> covered;  // triangles covering each pixel centre (before depth and alpha)
};

namespace reference_detail {

inline ReferenceVertex lerp(const ReferenceVertex& a, const ReferenceVertex& b, float t) {
  return {a.clip + (b.clip - a.clip) * t, a.world + (b.world - a.world) * t,
          a.normal + (b.normal - a.normal) * t, a.uv + (b.uv - a.uv) * t};
}

// Near clipping (z >= -w) into a polygon of 3 or 4 vertices, fanned from its first vertex.
inline int clip_near(const ReferenceVertex in[3], ReferenceVertex out[6]) {
  ReferenceVertex poly[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const ReferenceVertex &a = in[i], &b = in[(i + 1) % 3];
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

inline double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

inline void draw(const ReferenceVertex in[3], const glm::vec4& data, const MeshPass& pass,
                 ReferenceImages& out) {
  const int width = out.colour.width, height = out.colour.height;
  glm::dvec2 p[3];
  double inv_w[3], depth[3];
  for (int k = 0; k < 3; ++k) {
    const glm::vec4& c = in[k].clip;
    const double w = c.w;
    p[k] = glm::dvec2((c.x / w * 0.5 + 0.5) * width, (c.y / w * 0.5 + 0.5) * height);
    inv_w[k] = 1.0 / w;
    depth[k] = c.z / w * 0.5 + 0.5;
  }
  const double signed_area = edge(p[0], p[1], p[2]);
  if (signed_area == 0.0) return;
  const bool front = signed_area > 0.0;
  if ((pass.cull == CullMode::Back && !front) || (pass.cull == CullMode::Front && front)) return;
  const int o[3] = {0, front ? 1 : 2, front ? 2 : 1};  // counter-clockwise
  const glm::dvec2 q[3] = {p[o[0]], p[o[1]], p[o[2]]};
  const double area = edge(q[0], q[1], q[2]);
  for (int wy = 0; wy < height; ++wy)
    for (int wx = 0; wx < width; ++wx) {
      const glm::dvec2 centre(wx + 0.5, wy + 0.5);
      double b[3];
      bool inside = true;
      for (int k = 0; k < 3; ++k) {
        const glm::dvec2 &a = q[(k + 1) % 3], &c = q[(k + 2) % 3];
        b[k] = edge(a, c, centre);
        const bool top_left = (c.y - a.y == 0.0 && c.x - a.x < 0.0) || c.y - a.y < 0.0;
        inside = inside && (b[k] > 0.0 || (b[k] == 0.0 && top_left));
      }
      if (!inside) continue;
      const int x = wx, y = height - 1 - wy;
      ++out.covered[size_t(y * width + x)];
      const double l0 = b[0] / area, l1 = b[1] / area, l2 = b[2] / area;
      const float z = float(l0 * depth[o[0]] + l1 * depth[o[1]] + l2 * depth[o[2]]);
      if (z < 0.0f || z > 1.0f) continue;
      if (pass.depth_test != DepthTest::Off && !(z < out.depth.at(x, y)[0])) continue;
      const double q0 = l0 * inv_w[o[0]], q1 = l1 * inv_w[o[1]], q2 = l2 * inv_w[o[2]];
      const double qs = q0 + q1 + q2;
      const float w0 = float(q0 / qs), w1 = float(q1 / qs), w2 = float(q2 / qs);
      const ReferenceVertex &v0 = in[o[0]], &v1 = in[o[1]], &v2 = in[o[2]];
      MeshFragment f;
      f.world_position = v0.world * w0 + v1.world * w1 + v2.world * w2;
      f.world_normal = v0.normal * w0 + v1.normal * w1 + v2.normal * w2;
      f.uv = v0.uv * w0 + v1.uv * w1 + v2.uv * w2;
      f.instance_data = data;
      f.front_facing = front;
      const glm::vec4 c = pass.shade(f);
      if (c.a < pass.alpha_cutoff) continue;
      if (pass.depth_test != DepthTest::TestOnly) out.depth.at(x, y)[0] = z;
      for (int i = 0; i < 4; ++i) out.colour.at(x, y)[i] = c[i];
    }
}

}  // namespace reference_detail

// The images of `pass` on cleared targets (colour 0, depth 1) of width x height.
inline ReferenceImages reference_mesh_pass(const MeshPass& pass, int width, int height) {
  ReferenceImages out{ImageRGBA(width, height), ImageRGBA(width, height),
                      std::vector<int>(size_t(width * height), 0)};
  for (float& v : out.depth.pixels) v = 1.0f;
  const glm::mat4 view_proj = pass.view->projection * pass.view->view;
  const TriangleMesh& m = *pass.mesh;
  for (const MeshInstance& inst : pass.instances)
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      ReferenceVertex v[3];
      for (int k = 0; k < 3; ++k) {
        const unsigned i = m.index(t * 3 + size_t(k));
        const glm::vec3 pos(m.positions[i * 3], m.positions[i * 3 + 1], m.positions[i * 3 + 2]);
        const glm::vec3 nrm(m.normals[i * 3], m.normals[i * 3 + 1], m.normals[i * 3 + 2]);
        v[k].world = glm::vec3(inst.model * glm::vec4(pos, 1.0f));
        v[k].normal = glm::mat3(inst.model) * nrm;
        v[k].uv = glm::vec2(m.uvs[i * 2], m.uvs[i * 2 + 1]);
        v[k].clip = view_proj * glm::vec4(v[k].world, 1.0f);
      }
      ReferenceVertex clipped[6];
      const int n = reference_detail::clip_near(v, clipped);
      for (int c = 0; c < n; ++c) reference_detail::draw(clipped + c * 3, inst.data, pass, out);
    }
  return out;
}

}  // namespace sdfreel::test
