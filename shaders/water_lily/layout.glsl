// water_lily layout: the twin of src/scenes/water_lily/layout.h (same names and values).

// ---- flowers ----
const int FLOWER_COUNT = 5;
struct FlowerPlacement {
  vec2 xz;
  float scale;
  float turn;
  float phase;
};
const FlowerPlacement FLOWERS[FLOWER_COUNT] = FlowerPlacement[FLOWER_COUNT](
    FlowerPlacement(vec2(0.15, 1.3), 1.0, 0.0, 0.0),
    FlowerPlacement(vec2(-1.55, 2.75), 0.85, 0.3, 1.7),
    FlowerPlacement(vec2(1.75, 3.5), 0.9, 0.9, 3.1),
    FlowerPlacement(vec2(-0.55, 5.6), 0.8, 0.5, 4.4),
    FlowerPlacement(vec2(2.55, 7.4), 0.95, 0.2, 5.5));

const int PETAL_LAYERS = 3;
const int PETALS_PER_LAYER = 8;
struct PetalLayer {
  float reach;
  vec3 radii;
  float base_y;
  float curl;
  float turn;
};
const PetalLayer LAYERS[PETAL_LAYERS] = PetalLayer[PETAL_LAYERS](
    PetalLayer(0.31, vec3(0.31, 0.026, 0.105), 0.05, 0.45, 0.0),
    PetalLayer(0.24, vec3(0.25, 0.022, 0.088), 0.07, 1.0, 0.392699),
    PetalLayer(0.15, vec3(0.17, 0.018, 0.066), 0.09, 2.1, 0.19635));
const float PETAL_POINT = 0.4;
const float CENTER_RADIUS = 0.075;
const float CENTER_Y = 0.115;
const float CENTER_BLEND = 0.04;
const float LAYER_BLEND = 0.015;
const float FLOWER_BOUND_Y = 0.14;
const float FLOWER_BOUND_RADIUS = 0.72;
const float MAX_CURL = 2.0;

// ---- lily pads ----
const int LEAF_COUNT = 13;
struct LeafPlacement {
  vec2 xz;
  float radius;
  float notch_angle;
  float curl;
};
const LeafPlacement LEAVES[LEAF_COUNT] = LeafPlacement[LEAF_COUNT](
    LeafPlacement(vec2(0.35, 1.15), 0.95, 2.3, 0.03),
    LeafPlacement(vec2(-1.45, 2.8), 0.78, 0.6, 0.025),
    LeafPlacement(vec2(1.95, 3.35), 0.85, 4.0, 0.03),
    LeafPlacement(vec2(-2.7, 1.05), 0.7, 5.2, 0.05),
    LeafPlacement(vec2(1.35, 0.05), 0.5, 1.1, 0.02),
    LeafPlacement(vec2(-0.35, 3.5), 0.6, 3.3, 0.04),
    LeafPlacement(vec2(-0.7, 5.75), 0.82, 1.9, 0.03),
    LeafPlacement(vec2(3.1, 5.45), 0.9, 0.3, 0.045),
    LeafPlacement(vec2(-3.3, 4.5), 1.05, 4.6, 0.035),
    LeafPlacement(vec2(0.95, 7.1), 0.9, 2.8, 0.03),
    LeafPlacement(vec2(2.8, 7.65), 0.82, 5.6, 0.025),
    LeafPlacement(vec2(-2.2, 8.6), 1.05, 0.9, 0.04),
    LeafPlacement(vec2(2.45, 1.7), 0.58, 3.7, 0.05));
const int DRIFTING_LEAF = 5;
const float LEAF_Y = 0.006;
const float LEAF_HALF_H = 0.006;
const float NOTCH_HALF_ANGLE = 0.2;
const float LEAF_CURL_REACH = 1.15;

// ---- submerged pads ----
const int SUBMERGED_COUNT = 4;
const LeafPlacement SUBMERGED[SUBMERGED_COUNT] = LeafPlacement[SUBMERGED_COUNT](
    LeafPlacement(vec2(0.9, 2.35), 0.6, 0.8, 0.0),
    LeafPlacement(vec2(-1.25, 4.3), 0.7, 2.6, 0.0),
    LeafPlacement(vec2(2.1, 5.7), 0.75, 4.2, 0.0),
    LeafPlacement(vec2(-3.0, 6.9), 0.85, 1.4, 0.0));
const float SUBMERGED_DEPTH = 0.12;

// ---- the slab of marched surfaces ----
const float SLAB_BOTTOM = -0.01;
const float SLAB_TOP = 0.62;
const vec3 FIELD_MIN = vec3(-4.6, SLAB_BOTTOM, -0.8);
const vec3 FIELD_MAX = vec3(4.3, SLAB_TOP, 10.0);
