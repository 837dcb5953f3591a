#pragma once
// The card's textures: the two prints (interlaced source views, interlace.h) stacked top to
// bottom as linear albedo, and the sheet's ridge normal map. Pure functions of their inputs; the
// prints come from the cached source views (source_views.h).
#include <memory>
#include <string>
#include <vector>

#include "render/shader_inputs.h"
#include "scenes/common/texture.h"
#include "scenes/lenticular_card/interlace.h"
#include "scenes/lenticular_card/source_views.h"

namespace sdfreel::lenticular_card {

constexpr int RIDGE_MAP_SIZE = 64;

struct CardPrints {
  int lenses = 0, views = 0, view_height = 0;
  std::shared_ptr<const Texture> print, ridges;
  std::shared_ptr<const Texture> print_by_strip;  // the CPU's copy of print: by_strip()
  uint64_t key = 0;                               // names the texels (Scene::shader_textures_key)
};

// The texels of an interlaced print of `views` strips a lens, strip by strip: texel (x, y) of
// print at (x / views, (x % views) * print.height + y). The CPU reads the print through it: the
// pixels of a row of the frame see one strip of neighbouring lenses, side by side here (16 texels
// apart in print), so its lookups stay in the cache.
Texture by_strip(const Texture& print, int views);

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
