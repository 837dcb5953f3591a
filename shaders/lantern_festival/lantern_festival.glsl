// lantern_festival on the GPU path: the twin of src/scenes/lantern_festival/scene.cpp (per-ray
// pipeline: lake, lanterns, reflections, sky, fog), with the same names and order of operations.
// A change in the C++ scene must be mirrored here: tests/osmesa compares the two backends'
// frames. prepare() runs on the host; its results arrive as u_lake, u_grid, u_light, u_sky and
// u_water (src/scenes/lantern_festival/uniforms.cpp), and the march settings as u_march.
#include "common/sample_loop.glsl"
#include "common/surface_output.glsl"
#include "lantern_festival/march.glsl"
#include "lantern_festival/shading.glsl"
#include "lantern_festival/sky.glsl"

// The scene's own members beside the per-frame structs: the water's look, the distance fog and
// the march modes (LanternFestivalScene::reference_march_ and march_.naive / hit_mask).
struct WaterUniforms {
  vec3 color;
  float reflection_strength;
  float fog_density;
  bool reference_march;  // Quality::Reference: the seed's sphere tracing of repeated()
  bool naive;            // MarchSettings::naive: plain sphere tracing, world-space epsilons
  bool hit_mask;         // MarchSettings::hit_mask: radiance = id of the primary hit
  int surface;           // MarchSettings::surface (common/surface_output.glsl)
};

uniform WaterUniforms u_water;

// MarchSettings::hit_mask output: which marched surface the primary ray hit.
const float HIT_ID_NONE = 0.0;
const float HIT_ID_LANTERN = 1.0;
const float HIT_ID_WATER = 2.0;

vec3 applyFog(vec3 col, float t) {
  precise float f = 1.0 - dm_exp(-u_water.fog_density * t);
  precise vec3 r = dm_mix(col, u_sky.fog_color, f);
  return r;
}

// Normal step at path length t: a pixel footprint, or (naive preset) a world-space constant.
float normalEps(float t, float pixel_angle) {
  if (u_water.naive) return u_march.normal_eps;  // world units
  precise float e = dm_max(u_march.normal_eps * t * pixel_angle, 1e-4);
  return e;
}

MarchLimits limits(int max_steps, float pixel_angle, float t_offset) {
  return MarchLimits(max_steps, u_march.hit_eps, u_march.step_factor, pixel_angle, t_offset,
                     u_water.naive);
}

CellHit marchLanterns(vec3 o, vec3 dir, float t_max, MarchLimits lim, inout RayStats stats) {
  if (u_water.naive) {
    NaiveHit h = marchNaive(o, dir, t_max, false, lim, stats);
    return CellHit(h.hit, h.t, h.cell);
  }
  if (!u_water.reference_march) return marchCells(o, dir, 0.0, t_max, lim, stats);
  // The seed's way: sphere tracing of repeated(), then the lantern nearest to the hit.
  MarchHit h = march(o, dir, 0.0, t_max, lim, stats);
  if (!h.hit) return CellHit(false, 0.0, NO_CELL);
  precise vec3 p = o + dir * h.t;
  return CellHit(true, h.t, nearestLantern(p).cell);
}

// t_total: distance from the eye (sets the normal's footprint).
vec3 shadeLanternHit(vec3 o, vec3 dir, CellHit hit, float t_total, float pixel_angle) {
  precise vec3 p = o + dir * hit.t;
  precise float eps = normalEps(t_total, pixel_angle);
  LanternHit h;
  h.p = p;
  h.n = lanternNormal(hit.cell, p, eps);
  h.view = -dir;
  precise vec3 local = toLocal(hit.cell, p - hit.cell.center) * u_grid.inv_scale;
  h.local = local;
  h.cell = hit.cell;
  return shadeLantern(h);
}

vec3 shadeWater(vec3 p, vec3 dir, float t, float pixel_angle, inout RayStats stats) {
  precise float eps = normalEps(t, pixel_angle);
  precise vec3 normal = waterNormal(p, eps);
  precise vec3 r = dir - normal * (2.0 * dm_dot(normal, dir));  // reflect(dir, normal)
  MarchLimits lim = limits(u_march.reflect_steps, pixel_angle, t);
  CellHit hit = marchLanterns(p, r, u_march.max_dist, lim, stats);
  precise vec3 reflected;
  if (hit.hit) {
    precise float t_total = t + hit.t;
    reflected = shadeLanternHit(p, r, hit, t_total, pixel_angle);
  } else {
    reflected = skyReflected(r);
  }
  precise vec3 col = reflected * u_water.reflection_strength + u_water.color;
  return col;
}

// The naive preset: one plain sphere trace of lanterns and lake together.
void marchPrimaryNaive(Ray ray, out MarchHit water, out CellHit lantern, inout RayStats stats) {
  MarchLimits lim = limits(u_march.max_steps, ray.pixel_angle, 0.0);
  NaiveHit h = marchNaive(ray.origin, ray.dir, u_march.max_dist, true, lim, stats);
  water = MarchHit(h.hit && h.water, h.t);
  lantern = CellHit(h.hit && !h.water, h.t, h.cell);
}

vec3 radiance(Ray ray, inout RayStats stats) {
  MarchHit water;
  CellHit lantern;
  if (u_water.naive) {
    marchPrimaryNaive(ray, water, lantern, stats);
  } else {
    MarchLimits lim = limits(u_march.max_steps, ray.pixel_angle, 0.0);
    water = marchWater(ray.origin, ray.dir, u_march.max_dist, lim, stats);
    precise float t_far = water.hit ? water.t : u_march.max_dist;
    lantern = marchLanterns(ray.origin, ray.dir, t_far, lim, stats);
  }
  if (u_water.hit_mask)
    return vec3(lantern.hit ? HIT_ID_LANTERN : water.hit ? HIT_ID_WATER : HIT_ID_NONE);
  if (u_water.surface != SURFACE_COLOUR) {  // the depth and normal passes
    if (lantern.hit) {
      precise vec3 p = ray.origin + ray.dir * lantern.t;
      precise vec3 n = lanternNormal(lantern.cell, p, normalEps(lantern.t, ray.pixel_angle));
      precise vec3 r_ = surfaceOutput(u_water.surface, lantern.t, n);
      return r_;
    }
    if (water.hit) {
      precise vec3 p = ray.origin + ray.dir * water.t;
      precise vec3 n = waterNormal(p, normalEps(water.t, ray.pixel_angle));
      precise vec3 r_ = surfaceOutput(u_water.surface, water.t, n);
      return r_;
    }
    precise vec3 r_ = noSurface(u_water.surface);
    return r_;
  }
  if (lantern.hit)
    return applyFog(
        shadeLanternHit(ray.origin, ray.dir, lantern, lantern.t, ray.pixel_angle), lantern.t);
  if (water.hit) {
    precise vec3 p = ray.origin + ray.dir * water.t;
    return applyFog(shadeWater(p, ray.dir, water.t, ray.pixel_angle, stats), water.t);
  }
  return sky(ray.dir);
}
