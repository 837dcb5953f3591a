#include "embree_ids.h"

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>

#include "render/camera.h"
#include "render/tiling.h"

namespace sdfreel::mesh_bench {

struct EmbreeIds::PassGeometry {
  const MeshPass* pass;
  const FlatTriangles* flat;
  std::vector<uint32_t> id_of_prim;  // Embree's primID -> triangle id
  std::vector<bool> front;           // per kept prim
};

namespace {

std::atomic<uint64_t> alpha_tests{0};

// Alpha discard: the scene's shading at the candidate hit, rejected below the pass's cutoff.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* g = static_cast<const EmbreeIds::PassGeometry*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    alpha_tests.fetch_add(1, std::memory_order_relaxed);
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    const uint32_t id = g->id_of_prim[prim];
    const float w0 = 1.0f - u - v;
    MeshFragment f;
    const glm::vec3* p = &g->flat->world[size_t(id) * 3];
    const glm::vec2* t = &g->flat->uv[size_t(id) * 3];
    f.world_position = p[0] * w0 + p[1] * u + p[2] * v;
    f.world_normal = glm::vec3(0.0f, 1.0f, 0.0f);  // alpha never reads it
    f.uv = t[0] * w0 + t[1] * u + t[2] * v;
    f.instance_data = g->pass->instances[g->flat->instance_of[id]].data;
    f.front_facing = g->front[prim];
    if (g->pass->shade(f).a < g->pass->alpha_cutoff) args->valid[i] = 0;
  }
}

// The sign of the triangle's window-space area, from world space: > 0 counter-clockwise as the
// eye at `eye` sees it.
double facing(const glm::vec3* v, const glm::vec3& eye) {
  const glm::dvec3 a(v[0]), b(v[1]), c(v[2]);
  return glm::dot(glm::cross(b - a, c - a), glm::dvec3(eye) - a);
}

struct RayRange {
  float tnear, tfar;
};

// t on a unit ray between the near and far planes (view depth d = t * dot(dir, forward)).
RayRange ray_range(const BenchCase& c, const glm::vec3& dir) {
  const float along = glm::dot(dir, c.ctx.camera.forward);
  return {c.camera.near_plane / along, c.camera.far_plane / along};
}

void store_hit(const BenchCase& c, const std::vector<std::unique_ptr<EmbreeIds::PassGeometry>>& g,
               unsigned geom, unsigned prim, float t, const glm::vec3& dir, SampleHits& out,
               size_t at) {
  if (geom == RTC_INVALID_GEOMETRY_ID) return;
  out.id[at] = g[geom]->id_of_prim[prim] + 1;
  out.depth[at] = window_depth(c.camera, t * glm::dot(dir, c.ctx.camera.forward));
}

}  // namespace

uint64_t take_embree_alpha_tests() {
  return alpha_tests.exchange(0);
}

EmbreeIds::EmbreeIds(int threads, RTCBuildQuality quality, const std::string& isa)
    : quality_(quality) {
  std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  if (!isa.empty()) config += (config.empty() ? "isa=" : ",isa=") + isa;
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("rtcNewDevice(\"" + config + "\") failed");
}

EmbreeIds::~EmbreeIds() {
  release_scene();
  rtcReleaseDevice(device_);
}

std::string EmbreeIds::describe() const {
  const auto property = [this](RTCDeviceProperty p) { return rtcGetDeviceProperty(device_, p); };
  static const char* const tasking[] = {"internal", "TBB", "PPL"};
  const ssize_t t = property(RTC_DEVICE_PROPERTY_TASKING_SYSTEM);
  return std::string("Embree ") + RTC_VERSION_STRING + ", native 8-wide packets: " +
         (property(RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) ? "yes" : "no") +
         ", tasking: " + (t >= 0 && t < 3 ? tasking[t] : "?");
}

void EmbreeIds::release_scene() {
  if (scene_) rtcReleaseScene(scene_);
  scene_ = nullptr;
  geometries_.clear();
}

void EmbreeIds::build(const BenchCase& c, const FlatTriangles& flat) {
  release_scene();
  case_ = &c;
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, quality_);
  const glm::vec3 eye = c.ctx.camera.origin;
  for (size_t p = 0; p < c.passes.size(); ++p) {
    auto g = std::make_unique<PassGeometry>();
    g->pass = &c.passes[p];
    g->flat = &flat;
    const uint32_t first = flat.first_of_pass[p], end = flat.first_of_pass[p + 1];
    for (uint32_t t = first; t < end; ++t) {
      const double s = facing(&flat.world[size_t(t) * 3], eye);
      const bool keep = s != 0.0 && (g->pass->cull == CullMode::None ||
                                     (g->pass->cull == CullMode::Back) == (s > 0.0));
      if (!keep) continue;
      g->id_of_prim.push_back(t);
      g->front.push_back(s > 0.0);
    }
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t vertices = size_t(end - first) * 3;
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices));
    std::memcpy(vb, &flat.world[size_t(first) * 3], vertices * 3 * sizeof(float));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), g->id_of_prim.size()));
    for (size_t i = 0; i < g->id_of_prim.size(); ++i)
      for (unsigned k = 0; k < 3; ++k) ib[i * 3 + k] = (g->id_of_prim[i] - first) * 3 + k;
    rtcSetGeometryUserData(geom, g.get());
    if (g->pass->alpha_cutoff > 0.0f) rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene_, geom, unsigned(p));
    rtcReleaseGeometry(geom);
    geometries_.push_back(std::move(g));
  }
  rtcCommitScene(scene_);
}

SampleHits EmbreeIds::trace(int threads, bool packets) const {
  const BenchCase& c = *case_;
  const FrameContext& f = c.ctx;
  SampleHits out(f.width, f.height, int(f.sample_offsets.size()));
  const glm::vec3 eye = f.camera.origin;
  for_each_tile(f.width, f.height, 16, threads, [&](const Tile& tile) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (int s = 0; s < out.samples; ++s) {
      const glm::vec2 o = f.sample_offsets[size_t(s)];
      for (int y = tile.y0; y < tile.y1; ++y) {
        if (!packets) {
          for (int x = tile.x0; x < tile.x1; ++x) {
            const glm::vec3 dir =
                primary_ray_dir(f.camera, float(x) + o.x, float(y) + o.y, f.width, f.height);
            const RayRange r = ray_range(c, dir);
            RTCRayHit rh{};
            rh.ray = {eye.x, eye.y, eye.z, r.tnear, dir.x, dir.y, dir.z, 0.0f, r.tfar, ~0u, 0u, 0u};
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene_, &context, &rh);
            store_hit(c, geometries_, rh.hit.geomID, rh.hit.primID, rh.ray.tfar, dir, out,
                      out.index(s, x, y));
          }
          continue;
        }
        for (int x0 = tile.x0; x0 < tile.x1; x0 += 8) {
          alignas(32) RTCRayHit8 rh;
          alignas(32) int valid[8];
          glm::vec3 dirs[8];
          for (int i = 0; i < 8; ++i) {
            const int x = x0 + i;
            valid[i] = x < tile.x1 ? -1 : 0;
            dirs[i] = primary_ray_dir(f.camera, float(std::min(x, tile.x1 - 1)) + o.x,
                                      float(y) + o.y, f.width, f.height);
            const RayRange r = ray_range(c, dirs[i]);
            rh.ray.org_x[i] = eye.x, rh.ray.org_y[i] = eye.y, rh.ray.org_z[i] = eye.z;
            rh.ray.dir_x[i] = dirs[i].x, rh.ray.dir_y[i] = dirs[i].y, rh.ray.dir_z[i] = dirs[i].z;
            rh.ray.tnear[i] = r.tnear, rh.ray.tfar[i] = r.tfar, rh.ray.time[i] = 0.0f;
            rh.ray.mask[i] = ~0u, rh.ray.id[i] = 0u, rh.ray.flags[i] = 0u;
            rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
          }
          rtcIntersect8(valid, scene_, &context, &rh);
          for (int i = 0; i < 8 && x0 + i < tile.x1; ++i)
            store_hit(c, geometries_, rh.hit.geomID[i], rh.hit.primID[i], rh.ray.tfar[i], dirs[i],
                      out, out.index(s, x0 + i, y));
        }
      }
    }
  });
  return out;
}

}  // namespace sdfreel::mesh_bench
