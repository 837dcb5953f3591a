#pragma once
// water_lily geometry: lilies from layers of reshaped spheres and lily pads from a flattened
// cylinder with a notch, after seed 001. The water plane y = 0 is not marched (render.cpp).
// Mirrored line for line in shaders/water_lily/geometry.glsl.
#include <glm/glm.hpp>
#include <utility>

#include "scenes/water_lily/lanes_math.h"
#include "scenes/water_lily/layout.h"
#include "scenes/water_lily/uniforms.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"
#include "sdf/sdf.h"

namespace sdfreel::water_lily {

constexpr float PETAL_DIV = dm::TWO_PI / float(PETALS_PER_LAYER);  // angle per petal
// The blanket factor of the Shadertoy the seed cites (4sKBW3), kept by the naive preset.
constexpr float NAIVE_PETAL_FACTOR = 0.1f;
constexpr float BIG_DISTANCE = 1e10f;
constexpr float MIN_ELLIPSOID_GRADIENT = 1e-6f;

// The geometry is one source for the scalar path (glm::vec3, float) and the eight-lane path
// (V3x8, F8: lanes.cpp), as sdf/sdf.h: branches on the point are selects of both sides, so each
// lane performs the scalar operations in the scalar order and gets the scalar bits.
template <class V>
using DistanceOf = decltype(vlength(std::declval<V>()));

// A bound and a penumbra estimate, for one point or eight.
template <class F>
struct Dist2 {
  F x;  // the bound sphere tracing steps with
  F y;  // the penumbra estimate of the soft shadows
};

// The seed's flattened sphere: the sphere of radius r.x fed the point scaled by r.x / r, an
// ellipsoid with half axes r. Its Lipschitz constant is the largest scale, r.x / r.y (12 for the
// outer petals): the 0.1 of the Shadertoy the seed cites is not even a bound once the polar fold
// and the curl stretch it further (tests/scenes/water_lily/bounds_test.cpp). The naive preset
// keeps it with that blanket factor.
template <class V>
inline auto sdFlattenedSphere(const V& p, const glm::vec3& r) {
  return sdSphere(p * (r.x / r), r.x);
}

// The same sphere made a distance again (Quilez's ellipsoid bound): f = |p / r| - 1 divided by
// the length of its gradient. f is convex, so f / |grad f| never exceeds the distance to the
// ellipsoid from outside: a lower bound, tight near the surface from every side (not Lipschitz
// far away, which sphere tracing does not need).
template <class V>
inline auto ellipsoidBound(const V& p, const glm::vec3& r) {
  const auto k0 = vlength(p / r);
  const auto k1 = vlength(p / (r * r));
  return k0 * (k0 - 1.0f) / dm::max(k1, MIN_ELLIPSOID_GRADIENT);
}

// Spectral norm of [[m, k], [0, m]] (m, k >= 0): the largest stretch of a shear-like map.
inline float shearNorm(float m, float k) {
  return 0.5f * (dm::sqrt(4.0f * m * m + k * k) + k);
}

// Lipschitz bound of the reshaping of one petal layer at curl rate c (per-flower curl times the
// layer's): the product of the stretches of its maps, each a spectral norm. The pointed polar
// map r = rho (1 + k |a|) has Jacobian [[m, k], [0, m]] in (radial, tangential) frames,
// m = 1 + k |a| with |a| up to one division (the neighbour petal); the curl's twist (angle
// c min(s, extent)) has [[1, 0], [c s, 1]] with c s <= c * extent. A map stretching at most L
// brings no point more than L times closer to the petal: the ellipsoid bound / L is a distance
// bound in the world (tests/scenes/water_lily/bounds_test.cpp checks empty unbounding spheres).
inline float petalLipschitz(const PetalLayer& layer, float c) {
  const float polar = shearNorm(1.0f + PETAL_POINT * PETAL_DIV, PETAL_POINT);
  const float twist = shearNorm(1.0f, c * (layer.reach + layer.radii.x));
  return polar * twist;
}

// The seed's flattened sphere scales by up to this much more.
inline float flattenLipschitz(const PetalLayer& layer) {
  return layer.radii.x / layer.radii.y;
}

// Lipschitz bound of a pad whose rim is lifted by curl (rho / R)^2: the lift's slope at its reach.
inline float leafLipschitz(const LeafPlacement& leaf) {
  const float slope = 2.0f * leaf.curl * LEAF_CURL_REACH / leaf.radius;
  return shearNorm(1.0f, slope);
}

// One petal of a layer, at polar radius rho and angle a off its axis, height y above the layer's
// plane (flower units). Pointed: r = rho (1 + k |a|); curled: the (x, y) plane turned back by
// c * min(s, extent); flattened and fed to the sphere. Returns the seed's sphere value (not yet
// scaled) and the ellipsoid bound.
template <class F>
inline Dist2<F> petal(F rho, F a, F y, const PetalLayer& layer, float c) {
  const F r = rho * (1.0f + PETAL_POINT * dm::abs(a));
  const F x = r * dm::cos(a);
  const F z = r * dm::sin(a);
  const F s = dm::sqrt(x * x + y * y);
  const F phi = c * dm::min(s, layer.reach + layer.radii.x);
  const F cs = dm::cos(phi), sn = dm::sin(phi);
  const F xc = cs * x + sn * y;
  const F yc = cs * y - sn * x;
  const auto e = vec3_of(xc - layer.reach, yc, z);
  return {sdFlattenedSphere(e, layer.radii), ellipsoidBound(e, layer.radii)};
}

// One layer of PETALS_PER_LAYER petals around the flower axis: the point's angle folded into one
// division, and the petal of the neighbouring division too (a curled petal reaches over the
// border). q in flower units, relative to the flower's centre on the water. Returns the bound
// (ellipsoid bound / the reshaping's Lipschitz bound; naive: the seed's sphere * 0.1) and the
// penumbra estimate (the ellipsoid bound itself: near the true distance close to a petal).
template <class V>
inline Dist2<DistanceOf<V>> petalLayer(const V& q, int l, float turn, float c,
                                       const LilyUniforms& u) {
  using F = DistanceOf<V>;
  const PetalLayer& layer = LAYERS[l];
  const F rho = dm::sqrt(q.x * q.x + q.z * q.z);
  const F angle = dm::atan2(q.z, q.x) - (turn + layer.turn);
  const F a = dm::mod(angle, PETAL_DIV) - 0.5f * PETAL_DIV;
  const F a2 = select(a >= 0.0f, a - PETAL_DIV, a + PETAL_DIV);
  const F y = q.y - layer.base_y;
  const float cl = c * layer.curl;
  const Dist2<F> p1 = petal(rho, a, y, layer, cl);
  const Dist2<F> p2 = petal(rho, a2, y, layer, cl);
  const F e = dm::min(p1.y, p2.y);
  const F bound = u.naive ? dm::min(p1.x, p2.x) * NAIVE_PETAL_FACTOR : e / u.petal_lipschitz[l];
  return {bound, e};
}

// The flower's coloured centre: a sphere of stamens.
template <class V>
inline auto flowerCenter(const V& q) {
  return sdSphere(q - glm::vec3(0.0f, CENTER_Y, 0.0f), CENTER_RADIUS);
}

template <class V>
inline V toFlower(const V& p, int f) {
  const FlowerPlacement& fl = FLOWERS[f];
  return (p - glm::vec3(fl.xz.x, 0.0f, fl.xz.y)) / fl.scale;
}

// A water lily: the layers blended where they meet, the centre blended into the inner petals.
// Returns the bound and the penumbra estimate (world units).
template <class V>
inline Dist2<DistanceOf<V>> lilyFlowerPair(const V& p, int f, const LilyUniforms& u) {
  using F = DistanceOf<V>;
  const FlowerPlacement& fl = FLOWERS[f];
  const V q = toFlower(p, f);
  Dist2<F> d = petalLayer(q, 0, fl.turn, u.curl[f], u);
  for (int l = 1; l < PETAL_LAYERS; ++l) {
    const Dist2<F> e = petalLayer(q, l, fl.turn, u.curl[f], u);
    d = {opSmoothUnion(d.x, e.x, LAYER_BLEND), opSmoothUnion(d.y, e.y, LAYER_BLEND)};
  }
  const F c = flowerCenter(q);
  d = {opSmoothUnion(d.x, c, CENTER_BLEND), opSmoothUnion(d.y, c, CENTER_BLEND)};
  return {d.x * fl.scale, d.y * fl.scale};
}

template <class V>
inline DistanceOf<V> lilyFlower(const V& p, int f, const LilyUniforms& u) {
  return lilyFlowerPair(p, f, u).x;
}

inline glm::vec2 leafCenter(int i, const LilyUniforms& u) {
  return i == DRIFTING_LEAF ? LEAVES[i].xz + u.drift_offset : LEAVES[i].xz;
}

// Pad-local frame: centred, rim lift removed (curled leaves), turned so the notch opens along +x.
template <class V>
inline V toLeaf(const V& p, int i, const LilyUniforms& u) {
  using F = DistanceOf<V>;
  const LeafPlacement& leaf = LEAVES[i];
  const glm::vec2 c = leafCenter(i, u);
  const V q = p - glm::vec3(c.x, LEAF_Y, c.y);
  const F rho = dm::sqrt(q.x * q.x + q.z * q.z);
  const F e = dm::min(rho, leaf.radius * LEAF_CURL_REACH) / leaf.radius;
  const F lift = leaf.curl * e * e;
  const float cs = dm::cos(leaf.notch_angle), sn = dm::sin(leaf.notch_angle);
  return vec3_of(cs * q.x + sn * q.z, q.y - lift, cs * q.z - sn * q.x);
}

// The notch: two boxes, each displaced so that one face runs through the pad's centre at
// +-NOTCH_HALF_ANGLE; their intersection is the V cut out of the pad.
template <class V>
inline DistanceOf<V> leafNotch(const V& q, float radius) {
  const float ca = dm::cos(NOTCH_HALF_ANGLE), sa = dm::sin(NOTCH_HALF_ANGLE);
  const glm::vec3 half(1.2f * radius, 0.2f, radius);
  const V qa = vec3_of(ca * q.x + sa * q.z - radius, q.y, ca * q.z - sa * q.x + radius);
  const V qb = vec3_of(ca * q.x - sa * q.z - radius, q.y, ca * q.z + sa * q.x - radius);
  return opIntersection(sdBox(qa, half), sdBox(qb, half));
}

// A lily pad: a flattened cylinder minus the notch.
template <class V>
inline DistanceOf<V> lilyPad(const V& p, int i, const LilyUniforms& u) {
  const V q = toLeaf(p, i, u);
  const auto pad = sdCappedCylinder(q, LEAF_HALF_H, LEAVES[i].radius);
  const auto d = opSubtraction(leafNotch(q, LEAVES[i].radius), pad);
  return u.naive ? d : d / u.leaf_lipschitz[i];
}

// ---- bounds: cheap lower bounds that stand in for far parts ----

template <class V>
inline DistanceOf<V> flowerBound(const V& p, int f) {
  const FlowerPlacement& fl = FLOWERS[f];
  const glm::vec3 c(fl.xz.x, FLOWER_BOUND_Y * fl.scale, fl.xz.y);
  return vlength(p - c) - FLOWER_BOUND_RADIUS * fl.scale;
}

template <class V>
inline DistanceOf<V> leafBound(const V& p, int i, const LilyUniforms& u) {
  using F = DistanceOf<V>;
  const glm::vec2 c = leafCenter(i, u);
  const F dx = p.x - c.x, dz = p.z - c.y;
  const F side = dm::sqrt(dx * dx + dz * dz) - LEAVES[i].radius;
  const F vertical = dm::abs(p.y - LEAF_Y) - (LEAF_HALF_H + LEAVES[i].curl);
  return dm::max(side, vertical);
}

// What a marched point is: which flower or leaf is nearest.
struct Nearest {
  float d = BIG_DISTANCE;
  float est = BIG_DISTANCE;  // penumbra estimate of the nearest part (soft shadows)
  bool exact = true;         // false: a bound stood in for the nearest part
  int flower = -1;           // index of the nearest flower, or -1
  int leaf = -1;             // index of the nearest leaf, or -1
};

// Every marched surface (`leaves` false: the flowers only). Parts whose bound exceeds `margin`
// contribute the bound (the naive preset uses no bounds).
inline Nearest mapNearest(const glm::vec3& p, const LilyUniforms& u, float margin,
                          bool leaves = true) {
  Nearest n;
  for (int i = 0; i < (leaves ? LEAF_COUNT : 0); ++i) {
    const float b = u.naive ? -1.0f : leafBound(p, i, u);
    const bool far = b > margin;
    const float d = far ? b : lilyPad(p, i, u);
    if (d < n.d) {
      n.d = d;
      n.est = d;
      n.exact = !far;
      n.leaf = i;
    }
  }
  for (int f = 0; f < FLOWER_COUNT; ++f) {
    const float b = u.naive ? -1.0f : flowerBound(p, f);
    const bool far = b > margin;
    const Dist2<float> d = far ? Dist2<float>{b, b} : lilyFlowerPair(p, f, u);
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

}  // namespace sdfreel::water_lily
