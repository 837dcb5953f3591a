#pragma once
// water_lily: where everything is and how big (world units ~ metres, +Y up, the pond's surface is
// the plane y = 0). Mirrored in shaders/water_lily/layout.glsl: change both.
#include <glm/glm.hpp>

namespace sdfreel::water_lily {

// ---- flowers: layers of reshaped spheres (geometry.h, lilyFlower) ----
constexpr int FLOWER_COUNT = 5;
struct FlowerPlacement {
  glm::vec2 xz;  // centre on the water
  float scale;   // uniform size factor
  float turn;    // rotation of the petal pattern, radians
  float phase;   // animation phase of the curl, radians
};
inline const FlowerPlacement FLOWERS[FLOWER_COUNT] = {
    {{0.15f, 1.3f}, 1.0f, 0.0f, 0.0f},  {{-1.55f, 2.75f}, 0.85f, 0.3f, 1.7f},
    {{1.75f, 3.5f}, 0.9f, 0.9f, 3.1f},  {{-0.55f, 5.6f}, 0.8f, 0.5f, 4.4f},
    {{2.55f, 7.4f}, 0.95f, 0.2f, 5.5f},
};

constexpr int PETAL_LAYERS = 3;
constexpr int PETALS_PER_LAYER = 8;
// One layer of petals, in flower units (scale 1). Each petal is the seed's sphere fed a flattened
// point (an ellipsoid with half axes `radii`) whose centre sits `reach` out along its axis.
struct PetalLayer {
  float reach;      // ellipsoid centre's distance from the flower axis
  glm::vec3 radii;  // half length (along the petal), half thickness, half width
  float base_y;     // height of the petal's plane above the water
  float curl;       // curl rate relative to the flower's animated curl
  float turn;       // angular offset of the layer (radians), so petals interleave
};
inline const PetalLayer LAYERS[PETAL_LAYERS] = {
    {0.31f, {0.31f, 0.026f, 0.105f}, 0.05f, 0.45f, 0.0f},
    {0.24f, {0.25f, 0.022f, 0.088f}, 0.07f, 1.0f, 0.392699f},
    {0.15f, {0.17f, 0.018f, 0.066f}, 0.09f, 2.1f, 0.19635f},
};
// Pointed petals: the polar radius grows with the angle off the petal's axis, r = rho (1 + k |a|).
constexpr float PETAL_POINT = 0.4f;
// The curl bends each petal up about the flower axis by curl * min(s, reach + radii.x) radians,
// s the distance from the axis in the petal's vertical plane: beyond the petal's tip the bend is
// rigid, which keeps the map's stretch (and so its Lipschitz bound) finite.
// The coloured centre: a squat sphere of stamens, smoothly blended into the inner petals.
constexpr float CENTER_RADIUS = 0.075f;
constexpr float CENTER_Y = 0.115f;
constexpr float CENTER_BLEND = 0.04f;
constexpr float LAYER_BLEND = 0.015f;
// Every flower (any curl up to MAX_CURL) lies inside this sphere, in flower units.
constexpr float FLOWER_BOUND_Y = 0.14f;
constexpr float FLOWER_BOUND_RADIUS = 0.72f;
constexpr float MAX_CURL = 2.0f;  // the largest per-flower curl prepare() hands out

// ---- lily pads: a flattened cylinder with a notch cut by two displaced boxes ----
constexpr int LEAF_COUNT = 13;
struct LeafPlacement {
  glm::vec2 xz;
  float radius;
  float notch_angle;  // direction of the notch, radians
  float curl;         // rim lift at the edge (curled leaves)
};
inline const LeafPlacement LEAVES[LEAF_COUNT] = {
    {{0.35f, 1.15f}, 0.95f, 2.3f, 0.03f}, {{-1.45f, 2.8f}, 0.78f, 0.6f, 0.025f},
    {{1.95f, 3.35f}, 0.85f, 4.0f, 0.03f}, {{-2.7f, 1.05f}, 0.7f, 5.2f, 0.05f},
    {{1.35f, 0.05f}, 0.5f, 1.1f, 0.02f},  {{-0.35f, 3.5f}, 0.6f, 3.3f, 0.04f},
    {{-0.7f, 5.75f}, 0.82f, 1.9f, 0.03f}, {{3.1f, 5.45f}, 0.9f, 0.3f, 0.045f},
    {{-3.3f, 4.5f}, 1.05f, 4.6f, 0.035f}, {{0.95f, 7.1f}, 0.9f, 2.8f, 0.03f},
    {{2.8f, 7.65f}, 0.82f, 5.6f, 0.025f}, {{-2.2f, 8.6f}, 1.05f, 0.9f, 0.04f},
    {{2.45f, 1.7f}, 0.58f, 3.7f, 0.05f},
};
constexpr int DRIFTING_LEAF = 5;       // the leaf that drifts in x and z (seed: "one leaf")
constexpr float LEAF_Y = 0.006f;       // centre height of the pads (they float just above y = 0)
constexpr float LEAF_HALF_H = 0.006f;  // half thickness
constexpr float NOTCH_HALF_ANGLE = 0.2f;
constexpr float LEAF_CURL_REACH = 1.15f;  // the rim lift stops growing beyond radius * this

// ---- submerged pads: flat discs under the surface, seen through the water ----
constexpr int SUBMERGED_COUNT = 4;
inline const LeafPlacement SUBMERGED[SUBMERGED_COUNT] = {
    {{0.9f, 2.35f}, 0.6f, 0.8f, 0.0f},
    {{-1.25f, 4.3f}, 0.7f, 2.6f, 0.0f},
    {{2.1f, 5.7f}, 0.75f, 4.2f, 0.0f},
    {{-3.0f, 6.9f}, 0.85f, 1.4f, 0.0f},
};
constexpr float SUBMERGED_DEPTH = 0.12f;

// ---- the box that holds every marched surface: rays are marched only inside it ----
constexpr float SLAB_BOTTOM = -0.01f;
constexpr float SLAB_TOP = 0.62f;  // above the tallest flower's petals at MAX_CURL
// Its extent on the water: every pad (the drifting one at any drift) and flower inside.
inline const glm::vec3 FIELD_MIN(-4.6f, SLAB_BOTTOM, -0.8f);
inline const glm::vec3 FIELD_MAX(4.3f, SLAB_TOP, 10.0f);

}  // namespace sdfreel::water_lily
