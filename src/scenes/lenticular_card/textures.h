#pragma once
// The card's textures: the two prints (interlaced source views, interlace.h) stacked top to
// bottom as linear albedo, and the sheet's ridge normal map. Pure functions of their inputs; the
// prints come from the cached source views (source_views.h).
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "render/shader_inputs.h"
#include "scenes/common/texture.h"
#include "scenes/lenticular_card/interlace.h"
#include "scenes/lenticular_card/source_views.h"

namespace sdfreel::lenticular_card {

constexpr int RIDGE_MAP_SIZE = 64;

// The prints as the CPU reads them: their sRGB bytes strip by strip, decoded by a table (4.7 MB
// where float texels took 14 MB: fewer fresh pages to fill at start-up, fewer cache misses). Texel
// (x, y) of the interlaced print (a over b) lies at (x / views, (x % views) * height + y) of a
// (width / views) x (height * views) image: the pixels of a row of the frame see one strip of
// neighbouring lenses, side by side here (`views` texels apart in the print).
struct StripPrint {
  int width = 0, height = 0, views = 0;  // of the interlaced print
  std::vector<uint8_t> rgbx;             // r, g, b, 0 a texel (one 32-bit load), the strips' order
  std::array<float, 256> decode{};       // a byte's linear albedo
  size_t index(int x, int y) const {
    return (size_t(x % views) * size_t(height) + size_t(y)) * size_t(width / views) +
           size_t(x / views);
  }
  glm::vec4 texel(int x, int y) const {
    const uint8_t* c = &rgbx[4 * index(x, y)];
    return glm::vec4(decode[c[0]], decode[c[1]], decode[c[2]], 1.0f);
  }
};

struct CardPrints {
  int lenses = 0, views = 0, view_height = 0;
  std::shared_ptr<const StripPrint> print;
  std::shared_ptr<const Texture> ridges;
  uint64_t key = 0;  // names the texels (Scene::shader_textures_key)
};

// The print as 4-channel float texels, row by row (GL's u_card_print; the plain definition the
// tests hold the strips to).
Texture print_texture(const StripPrint& print);

// One texel a strip: interlace() with one print pixel a strip and rows as in the views.
InterlaceLayout card_layout(int views);

// The prints of `a` over `b` (same view count and size), each interlaced, as 4-channel linear
// albedo: sRGB decoded, times PRINT_REFLECTANCE.
CardPrints make_card_prints(const std::vector<Rgb8Image>& a, const std::vector<Rgb8Image>& b);

// The exhibit's default prints: 16 views each of lantern_festival and sdf_morph (source views,
// cached), made once per process.
const CardPrints& default_card_prints();

// Tangent-space noise normals (x, y in [-1, 1]) of a tiling fractal height field.
Texture make_ridge_map(int n, uint32_t seed);

// The textures as the GLSL samplers u_card_print and u_card_ridges read them.
std::vector<ShaderTexture> card_shader_textures(const CardPrints& prints);

}  // namespace sdfreel::lenticular_card
