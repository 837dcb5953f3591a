// The unbounded, irregular grid of lanterns: the twin of src/scenes/lantern_festival/grid.{h,cpp}
// (same names, same order of operations). The per-frame GridFrame arrives as u_grid. The C++
// keeps a table of the cells near the camera; its entries are lanternCellAt() of the same id, so
// computing a cell here on demand gives the same bits.
#include "lantern_festival/lake.glsl"
#include "lantern_festival/lantern.glsl"
#include "lantern_festival/generated_textures.glsl"

// The seed's flicker is periodic: cos(2 pi T), cos(3 pi T) and cos(2.5 pi T) all repeat after 4.
const float FLICKER_PERIOD = 4.0;
// A lantern's yaw is free in [0, pi/2): the lantern has four-fold symmetry.
const float YAW_RANGE = DM_HALF_PI;

struct GridFrame {
  float size;        // cell spacing (world units)
  float max_offset;  // |blue-noise offset| per axis
  float scale;       // lantern size
  float inv_scale;
  float bound_radius;  // world bounding cylinder around a lantern's centre, tilt included
  float bound_half_height;
  float early_out;  // farther than this from the bound, the bound is the distance
  float extent;     // max-norm reach of a lantern from its grid point
  float slab_lo, slab_hi;
};

uniform GridFrame u_grid;

struct LanternCell {
  vec3 center;          // world position of the lantern's origin
  vec3 to_local[3];     // rows of the world -> lantern rotation
  float flicker_phase;  // added to the flicker clock
};

// LanternCell{} of the C++: what a miss carries.
const LanternCell NO_CELL =
    LanternCell(vec3(0.0), vec3[3](vec3(0.0), vec3(0.0), vec3(0.0)), 0.0);

vec4 blueNoiseAtID(vec2 id) { return texelFetchRepeat(u_blue_noise, id.x, id.y); }

// The seed's offset(blueNoise.xy): centred, scaled to the free room of the cell.
vec2 offset(vec2 bn) {
  precise vec2 o = (bn * 2.0 - 1.0) * u_grid.max_offset;
  return o;
}

LanternCell lanternCellAt(vec2 id) {
  precise vec4 bn = blueNoiseAtID(id);
  precise vec2 centre_xz = id * u_grid.size - offset(vec2(bn.x, bn.y));
  LanternCell c;
  // Float on the lake: the base (lantern y = -1) on the water at the centre.
  precise float centre_y = waterSurfaceY(centre_xz) + u_grid.scale;
  c.center = vec3(centre_xz.x, centre_y, centre_xz.y);
  // Tilt onto the rough wave's normal n, then yaw about the lantern's own axis.
  precise vec3 n = normalWaterRough(centre_xz);
  precise float k = 1.0 / (1.0 + n.y);
  precise vec3 X = vec3(1.0 - n.x * n.x * k, -n.x, -n.x * n.z * k);
  precise vec3 Z = vec3(-n.x * n.z * k, -n.z, 1.0 - n.z * n.z * k);
  precise float yaw = bn.w * YAW_RANGE;
  precise float cy = dm_cos(yaw), sy = dm_sin(yaw);
  precise vec3 row0 = X * cy + Z * sy;
  precise vec3 row2 = Z * cy - X * sy;
  precise float phase = bn.z * FLICKER_PERIOD;
  c.to_local[0] = row0;
  c.to_local[1] = n;
  c.to_local[2] = row2;
  c.flicker_phase = phase;
  return c;
}

// LanternField::cell: the table's entry in the C++, the same function here.
LanternCell fieldCell(vec2 id) { return lanternCellAt(id); }

vec3 toLocal(LanternCell c, vec3 d) {
  precise vec3 l = vec3(dm_dot(c.to_local[0], d), dm_dot(c.to_local[1], d),
                        dm_dot(c.to_local[2], d));
  return l;
}

vec3 toWorld(LanternCell c, vec3 v) {
  precise vec3 w = c.to_local[0] * v.x + c.to_local[1] * v.y + c.to_local[2] * v.z;
  return w;
}

// The seed's round(): floor(x + 0.5).
vec2 cellId(vec2 p) {
  precise float x = p.x / u_grid.size + 0.5, y = p.y / u_grid.size + 0.5;
  return vec2(floor(x), floor(y));
}

// One lantern's distance; far from its bounding cylinder the cylinder's distance stands in
// unless `exact`.
float lanternDistance(LanternCell c, vec3 p, bool exact) {
  precise vec3 d = p - c.center;
  if (!exact) {
    precise float bound = sdCappedCylinder(d, u_grid.bound_half_height, u_grid.bound_radius);
    if (bound > u_grid.early_out) return bound;
  }
  precise vec3 local = toLocal(c, d) * u_grid.inv_scale;
  precise float dist = sdfLantern(local) * u_grid.scale;
  return dist;
}

// sign() with sign(0) = +1.
float neighbourSign(float x) { return x < 0.0 ? -1.0 : 1.0; }

// The seed's loop: the lanterns of the 2 x 2 cells nearest to p.
float nearestFour(vec3 p3, bool exact) {
  precise vec2 p = vec2(p3.x, p3.z);
  precise vec2 id = cellId(p);
  precise float rx = p.x - u_grid.size * id.x, rz = p.y - u_grid.size * id.y;
  precise vec2 o = vec2(neighbourSign(rx), neighbourSign(rz));
  precise float d = 1e20;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      precise vec2 rid = id + vec2(float(i), float(j)) * o;
      d = dm_min(d, lanternDistance(fieldCell(rid), p3, exact));
    }
  return d;
}

// Lower bound of the distance to the lanterns of every other cell.
float othersBound(vec3 p3) {
  precise vec2 p = vec2(p3.x, p3.z);
  precise vec2 rel = p - u_grid.size * cellId(p);
  precise float b = dm_min(abs(rel.x), abs(rel.y)) + u_grid.size - u_grid.extent;
  return b;
}

// The lantern field: min(nearestFour, othersBound).
float repeated(vec3 p3, bool exact) { return dm_min(nearestFour(p3, exact), othersBound(p3)); }

struct NearestLantern {
  LanternCell cell;
  float distance;
};

// The lantern nearest to p among the 2 x 2 candidate cells, by exact distance (for shading).
NearestLantern nearestLantern(vec3 p3) {
  precise vec2 p = vec2(p3.x, p3.z);
  precise vec2 id = cellId(p);
  precise vec2 rel = p - u_grid.size * id;
  precise vec2 o = vec2(neighbourSign(rel.x), neighbourSign(rel.y));
  NearestLantern best = NearestLantern(fieldCell(id), 1e20);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      precise vec2 rid = id + vec2(float(i), float(j)) * o;
      LanternCell c = fieldCell(rid);
      precise float d = lanternDistance(c, p3, true);
      if (d < best.distance) best = NearestLantern(c, d);
    }
  return best;
}
