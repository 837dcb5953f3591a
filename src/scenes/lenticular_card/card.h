#pragma once
// The card on its stand, intersected analytically (two boxes) in the exhibit's local frame: the
// stand's base on y = 0, the card upright above it facing +z, its lenses running along y. A ray
// pass traces it (exhibit.h); GLSL twin shaders/lenticular_card/card.glsl.
#include <glm/glm.hpp>

#include "render/rays.h"
#include "scenes/common/texture.h"

namespace sdfreel::lenticular_card {

// Geometry, local units (metres). The card's face is 4:3 like the views.
constexpr float CARD_HALF_WIDTH = 0.32f;
constexpr float CARD_HALF_HEIGHT = 0.24f;
constexpr float CARD_HALF_THICKNESS = 0.004f;
constexpr float CARD_CENTRE_Y = 0.30f;
constexpr float BASE_HALF_WIDTH = 0.22f, BASE_HALF_HEIGHT = 0.03f, BASE_HALF_DEPTH = 0.09f;

// Per-frame constants of the card pass.
struct CardUniforms {
  glm::mat4 world_to_local{1.0f};       // inverse of the exhibit's model matrix
  glm::vec3 light{0.0f, 1.0f, 0.0f};    // unit direction toward the key light, local frame
  float scroll = 0.0f;                  // scroll_offset(), print heights in [0, 2)
  float ior = 1.56f, thickness = 1.5f;  // sheet: index of refraction, thickness / lens pitch
  float gloss = 1.0f, ridge_noise = 0.1f;
  int lenses = 64, views = 16, view_height = 48;  // the print's layout (textures.h)
  bool hit_mask = false;     // MarchSettings::hit_mask: ids instead of colours (card 1, stand 2)
  int surface = 0;           // MarchSettings::surface: the hit's distance or world normal
  float hit_id_base = 0.0f;  // added to those ids (a host scene keeps its own ids apart)
};

struct StripPrint;  // textures.h

// The textures the card reads: the interlaced prints (linear albedo) and the ridge normal map.
// The prints strip by strip (textures.h, StripPrint) when given, else as plain float texels
// (print_texture, as GL reads them): the same texels.
struct CardTextures {
  const StripPrint* print = nullptr;
  const Texture* ridges = nullptr;
  const Texture* plain_print = nullptr;  // read when `print` is null
};

// The world ray in the local frame: origin and direction times world_to_local, sums written out
// in one order (the GLSL twin adds the same products in the same order). Not renormalised, so a
// local hit's t is the world ray's t.
glm::vec3 to_local_point(const glm::mat4& m, const glm::vec3& p);
glm::vec3 to_local_direction(const glm::mat4& m, const glm::vec3& d);
V3x8 to_local_direction(const glm::mat4& m, const V3x8& d);  // the same, eight lanes

// Nearest entry t > 0 of the ray into the box (centre c, half sizes h), and the face's axis
// (0, 1, 2) in `axis`; false when it misses or starts inside.
bool hitBox(const glm::vec3& o, const glm::vec3& d, const glm::vec3& c, const glm::vec3& h,
            float& t, int& axis);

// The radiance of the card's front at local point p seen along local direction d.
glm::vec3 frontColour(const glm::vec3& p, const glm::vec3& d, const CardUniforms& u,
                      const CardTextures& tex);

// For a packet of world rays: false for lanes that surely miss the card and its stand (a slab test
// against their common box grown by a margin far above float rounding), so only the other lanes
// need shadeCard; the lanes it keeps are a superset of shadeCard's hits.
M8 may_hit_card(const RayPacket& rays, const CardUniforms& u);

// Shades one world ray: false on a miss; else the colour and the hit's t along the ray.
bool shadeCard(const Ray& ray, const CardUniforms& u, const CardTextures& tex, glm::vec3& colour,
               float& t);

}  // namespace sdfreel::lenticular_card
