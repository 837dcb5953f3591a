#pragma once
// water_lily look: the Monet palette (linear Rec.709) and the shading constants. Mirrored in
// shaders/water_lily/look.glsl.
#include <cstdint>
#include <glm/glm.hpp>

namespace sdfreel::water_lily {

// ---- sky: pale warm horizon, soft blue zenith, FBM cloud glow, sun glow ----
inline const glm::vec3 SKY_HORIZON(0.70f, 0.74f, 0.80f);
inline const glm::vec3 SKY_ZENITH(0.32f, 0.48f, 0.78f);
inline const glm::vec3 CLOUD_COLOR(0.95f, 0.90f, 0.88f);
constexpr float CLOUD_LIFT = 0.25f;  // clouds flatten towards the horizon: d.xz / (d.y + lift)
constexpr float CLOUD_SCALE = 1.3f;
constexpr int CLOUD_OCTAVES = 5;
constexpr uint32_t CLOUD_SEED = 101u;
constexpr float CLOUD_LOW = 0.45f, CLOUD_HIGH = 0.66f;
constexpr float CLOUD_WEIGHT = 0.6f;
constexpr float SUN_GLOW = 0.35f;

// ---- light ----
inline const glm::vec3 FILL_COLOR(0.16f, 0.20f, 0.28f);   // the blue sky as a light from above
inline const glm::vec3 AMBIENT_SKY(0.10f, 0.12f, 0.15f);  // everything else around
inline const glm::vec3 FOG_COLOR(0.70f, 0.73f, 0.78f);
constexpr float FOG_START_SHARE = 0.25f;  // fog starts at this share of fog_distance

// ---- petals and centres ----
inline const glm::vec3 PETAL_WHITE(0.92f, 0.88f, 0.86f);
inline const glm::vec3 PETAL_PINK_TIP(0.90f, 0.62f, 0.72f);
inline const glm::vec3 PETAL_BASE(0.85f, 0.38f, 0.55f);
constexpr float PETAL_GRADIENT = 1.8f;     // how fast the pink base gives way to the tip colour
constexpr float PETAL_LAYER_PINK = 0.18f;  // inner layers are pinker
constexpr float PETAL_TIP_REACH = 0.62f;   // flower units: the outer petals' tips
inline const glm::vec3 PETAL_TRANSMIT(1.0f, 0.75f, 0.7f);  // sunlight through a petal, warmed
inline const glm::vec3 CENTER_YELLOW(0.95f, 0.68f, 0.08f);
inline const glm::vec3 CENTER_DEEP(0.75f, 0.32f, 0.04f);
constexpr float CENTER_COLOR_REACH = 0.02f;  // flower units: within this of the centre sphere

// ---- lily pads ----
inline const glm::vec3 LEAF_GREEN_A(0.05f, 0.16f, 0.035f);
inline const glm::vec3 LEAF_GREEN_B(0.12f, 0.24f, 0.05f);
inline const glm::vec3 LEAF_VEIN(0.22f, 0.34f, 0.10f);
inline const glm::vec3 LEAF_RIM(0.28f, 0.10f, 0.06f);
constexpr uint32_t LEAF_SEED = 211u;
constexpr float LEAF_CELL_FREQUENCY = 9.0f;  // Worley cells per unit
constexpr float LEAF_BORDER_WIDTH = 0.08f;
constexpr float LEAF_BORDER_WEIGHT = 0.45f;
constexpr float LEAF_VEIN_COUNT = 21.0f;
constexpr float LEAF_VEIN_DEPTH = 0.12f;
constexpr float LEAF_RIM_WEIGHT = 0.6f;
constexpr float LEAF_SHININESS = 24.0f;  // waxy pads
constexpr float LEAF_SPECULAR = 0.12f;

// ---- water ----
inline const glm::vec3 WATER_DEEP(0.03f, 0.07f, 0.10f);
inline const glm::vec3 UNDERWATER(0.03f, 0.08f, 0.07f);
constexpr float WATER_F0 = 0.02f;
constexpr float WATER_FREQUENCY = 1.5f;
constexpr int WATER_OCTAVES = 4;
constexpr uint32_t WATER_SEED = 307u;
constexpr float WATER_BUMP = 0.14f;
constexpr float WATER_DELTA = 0.02f;  // finite-difference step of the bump
constexpr float WATER_CALM_NEAR = 2.0f;
constexpr float WATER_CALM_FAR = 18.0f;
constexpr float WATER_SUN_SHARE = 0.6f;
constexpr float SUN_GLINT = 1.2f;
constexpr float SUN_GLINT_POWER = 180.0f;
constexpr float REFLECT_FALLOFF =
    0.08f;  // reflected lilies fade with the distance behind the water
inline const glm::vec3 SUBMERGED_GREEN(0.10f, 0.20f, 0.06f);
constexpr float SUBMERGED_TRANSMIT = 0.5f;
constexpr float SUBMERGED_EDGE = 0.03f;
constexpr float REFRACT_BEND = 0.75f;  // horizontal share kept by refraction (about 1 / 1.33)

// ---- grading ----
constexpr float SATURATION_GREY = 0.4f;  // the seed's dot(col, vec3(0.4))

}  // namespace sdfreel::water_lily
