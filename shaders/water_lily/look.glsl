// water_lily look: the twin of src/scenes/water_lily/look.h (same names and values).

const vec3 SKY_HORIZON = vec3(0.70, 0.74, 0.80);
const vec3 SKY_ZENITH = vec3(0.32, 0.48, 0.78);
const vec3 CLOUD_COLOR = vec3(0.95, 0.90, 0.88);
const float CLOUD_LIFT = 0.25;
const float CLOUD_SCALE = 1.3;
const int CLOUD_OCTAVES = 5;
const uint CLOUD_SEED = 101u;
const float CLOUD_LOW = 0.45, CLOUD_HIGH = 0.66;
const float CLOUD_WEIGHT = 0.6;
const float SUN_GLOW = 0.35;

const vec3 FILL_COLOR = vec3(0.16, 0.20, 0.28);
const vec3 AMBIENT_SKY = vec3(0.10, 0.12, 0.15);
const vec3 FOG_COLOR = vec3(0.70, 0.73, 0.78);
const float FOG_START_SHARE = 0.25;

const vec3 PETAL_WHITE = vec3(0.92, 0.88, 0.86);
const vec3 PETAL_PINK_TIP = vec3(0.90, 0.62, 0.72);
const vec3 PETAL_BASE = vec3(0.85, 0.38, 0.55);
const float PETAL_GRADIENT = 1.8;
const float PETAL_LAYER_PINK = 0.18;
const float PETAL_TIP_REACH = 0.62;
const vec3 PETAL_TRANSMIT = vec3(1.0, 0.75, 0.7);
const vec3 CENTER_YELLOW = vec3(0.95, 0.68, 0.08);
const vec3 CENTER_DEEP = vec3(0.75, 0.32, 0.04);
const float CENTER_COLOR_REACH = 0.02;

const vec3 LEAF_GREEN_A = vec3(0.05, 0.16, 0.035);
const vec3 LEAF_GREEN_B = vec3(0.12, 0.24, 0.05);
const vec3 LEAF_VEIN = vec3(0.22, 0.34, 0.10);
const vec3 LEAF_RIM = vec3(0.28, 0.10, 0.06);
const uint LEAF_SEED = 211u;
const float LEAF_CELL_FREQUENCY = 9.0;
const float LEAF_BORDER_WIDTH = 0.08;
const float LEAF_BORDER_WEIGHT = 0.45;
const float LEAF_VEIN_COUNT = 21.0;
const float LEAF_VEIN_DEPTH = 0.12;
const float LEAF_RIM_WEIGHT = 0.6;
const float LEAF_SHININESS = 24.0;
const float LEAF_SPECULAR = 0.12;

const vec3 WATER_DEEP = vec3(0.03, 0.07, 0.10);
const vec3 UNDERWATER = vec3(0.03, 0.08, 0.07);
const float WATER_F0 = 0.02;
const float WATER_FREQUENCY = 1.5;
const int WATER_OCTAVES = 4;
const uint WATER_SEED = 307u;
const float WATER_BUMP = 0.14;
const float WATER_DELTA = 0.02;
const float WATER_CALM_NEAR = 2.0;
const float WATER_CALM_FAR = 18.0;
const float WATER_SUN_SHARE = 0.6;
const float SUN_GLINT = 1.2;
const float SUN_GLINT_POWER = 180.0;
const float REFLECT_FALLOFF = 0.08;
const vec3 SUBMERGED_GREEN = vec3(0.10, 0.20, 0.06);
const float SUBMERGED_TRANSMIT = 0.5;
const float SUBMERGED_EDGE = 0.03;
const float REFRACT_BEND = 0.75;

const float SATURATION_GREY = 0.4;
