// water_lily geometry: the twin of src/scenes/water_lily/geometry.h (same names, same order of
// operations; every local precise).
#include "common/sdf.glsl"
#include "water_lily/uniforms.glsl"

const float PETAL_DIV = DM_TWO_PI / float(PETALS_PER_LAYER);
const float NAIVE_PETAL_FACTOR = 0.1;
const float BIG_DISTANCE = 1e10;
const float MIN_ELLIPSOID_GRADIENT = 1e-6;

float sdFlattenedSphere(vec3 p, vec3 r) { return sdSphere(p * (r.x / r), r.x); }

float ellipsoidBound(vec3 p, vec3 r) {
  precise float k0 = dm_length(p / r);
  precise float k1 = dm_length(p / (r * r));
  return k0 * (k0 - 1.0) / dm_max(k1, MIN_ELLIPSOID_GRADIENT);
}

vec2 petal(float rho, float a, float y, PetalLayer layer, float c) {
  precise float r = rho * (1.0 + PETAL_POINT * abs(a));
  precise float x = r * dm_cos(a);
  precise float z = r * dm_sin(a);
  precise float s = sqrt(x * x + y * y);
  precise float phi = c * dm_min(s, layer.reach + layer.radii.x);
  precise float cs = dm_cos(phi), sn = dm_sin(phi);
  precise float xc = cs * x + sn * y;
  precise float yc = cs * y - sn * x;
  precise vec3 e = vec3(xc - layer.reach, yc, z);
  return vec2(sdFlattenedSphere(e, layer.radii), ellipsoidBound(e, layer.radii));
}

vec2 petalLayer(vec3 q, int l, float turn, float c, LilyUniforms u) {
  PetalLayer layer = LAYERS[l];
  precise float rho = sqrt(q.x * q.x + q.z * q.z);
  precise float angle = dm_atan2(q.z, q.x) - (turn + layer.turn);
  precise float a = dm_mod(angle, PETAL_DIV) - 0.5 * PETAL_DIV;
  precise float a2 = a >= 0.0 ? a - PETAL_DIV : a + PETAL_DIV;
  precise float y = q.y - layer.base_y;
  precise float cl = c * layer.curl;
  precise vec2 p1 = petal(rho, a, y, layer, cl);
  precise vec2 p2 = petal(rho, a2, y, layer, cl);
  precise float e = dm_min(p1.y, p2.y);
  precise float bound =
      u.naive != 0 ? dm_min(p1.x, p2.x) * NAIVE_PETAL_FACTOR : e / u.petal_lipschitz[l];
  return vec2(bound, e);
}

float flowerCenter(vec3 q) { return sdSphere(q - vec3(0.0, CENTER_Y, 0.0), CENTER_RADIUS); }

vec3 toFlower(vec3 p, int f) {
  FlowerPlacement fl = FLOWERS[f];
  return (p - vec3(fl.xz.x, 0.0, fl.xz.y)) / fl.scale;
}

vec2 lilyFlowerPair(vec3 p, int f, LilyUniforms u) {
  FlowerPlacement fl = FLOWERS[f];
  precise vec3 q = toFlower(p, f);
  precise vec2 d = petalLayer(q, 0, fl.turn, u.curl[f], u);
  for (int l = 1; l < PETAL_LAYERS; ++l) {
    precise vec2 e = petalLayer(q, l, fl.turn, u.curl[f], u);
    d = vec2(opSmoothUnion(d.x, e.x, LAYER_BLEND), opSmoothUnion(d.y, e.y, LAYER_BLEND));
  }
  precise float c = flowerCenter(q);
  d = vec2(opSmoothUnion(d.x, c, CENTER_BLEND), opSmoothUnion(d.y, c, CENTER_BLEND));
  return d * fl.scale;
}

float lilyFlower(vec3 p, int f, LilyUniforms u) { return lilyFlowerPair(p, f, u).x; }

vec2 leafCenter(int i, LilyUniforms u) {
  return i == DRIFTING_LEAF ? LEAVES[i].xz + u.drift_offset : LEAVES[i].xz;
}

vec3 toLeaf(vec3 p, int i, LilyUniforms u) {
  LeafPlacement leaf = LEAVES[i];
  precise vec2 c = leafCenter(i, u);
  precise vec3 q = p - vec3(c.x, LEAF_Y, c.y);
  precise float rho = sqrt(q.x * q.x + q.z * q.z);
  precise float e = dm_min(rho, leaf.radius * LEAF_CURL_REACH) / leaf.radius;
  precise float lift = leaf.curl * e * e;
  precise float cs = dm_cos(leaf.notch_angle), sn = dm_sin(leaf.notch_angle);
  return vec3(cs * q.x + sn * q.z, q.y - lift, cs * q.z - sn * q.x);
}

float leafNotch(vec3 q, float radius) {
  precise float ca = dm_cos(NOTCH_HALF_ANGLE), sa = dm_sin(NOTCH_HALF_ANGLE);
  precise vec3 half_size = vec3(1.2 * radius, 0.2, radius);
  precise vec3 qa = vec3(ca * q.x + sa * q.z - radius, q.y, ca * q.z - sa * q.x + radius);
  precise vec3 qb = vec3(ca * q.x - sa * q.z - radius, q.y, ca * q.z + sa * q.x - radius);
  return opIntersection(sdBox(qa, half_size), sdBox(qb, half_size));
}

float lilyPad(vec3 p, int i, LilyUniforms u) {
  precise vec3 q = toLeaf(p, i, u);
  precise float pad = sdCappedCylinder(q, LEAF_HALF_H, LEAVES[i].radius);
  precise float d = opSubtraction(leafNotch(q, LEAVES[i].radius), pad);
  return u.naive != 0 ? d : d / u.leaf_lipschitz[i];
}

float flowerBound(vec3 p, int f) {
  FlowerPlacement fl = FLOWERS[f];
  precise vec3 c = vec3(fl.xz.x, FLOWER_BOUND_Y * fl.scale, fl.xz.y);
  return dm_length(p - c) - FLOWER_BOUND_RADIUS * fl.scale;
}

float leafBound(vec3 p, int i, LilyUniforms u) {
  precise vec2 c = leafCenter(i, u);
  precise float dx = p.x - c.x, dz = p.z - c.y;
  precise float side = sqrt(dx * dx + dz * dz) - LEAVES[i].radius;
  precise float vertical = abs(p.y - LEAF_Y) - (LEAF_HALF_H + LEAVES[i].curl);
  return dm_max(side, vertical);
}

struct Nearest {
  float d;
  float est;
  bool exact;
  int flower;
  int leaf;
};

Nearest mapNearest(vec3 p, LilyUniforms u, float margin, bool leaves) {
  Nearest n = Nearest(BIG_DISTANCE, BIG_DISTANCE, true, -1, -1);
  for (int i = 0; i < (leaves ? LEAF_COUNT : 0); ++i) {
    precise float b = u.naive != 0 ? -1.0 : leafBound(p, i, u);
    bool far = b > margin;
    precise float d = far ? b : lilyPad(p, i, u);
    if (d < n.d) {
      n.d = d;
      n.est = d;
      n.exact = !far;
      n.leaf = i;
    }
  }
  for (int f = 0; f < FLOWER_COUNT; ++f) {
    precise float b = u.naive != 0 ? -1.0 : flowerBound(p, f);
    bool far = b > margin;
    precise vec2 d = far ? vec2(b) : lilyFlowerPair(p, f, u);
    if (d.x < n.d) {
      n.d = d.x;
      n.est = d.y;
      n.exact = !far;
      n.flower = f;
      n.leaf = -1;
    }
  }
  return n;
}
