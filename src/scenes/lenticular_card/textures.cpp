#include "scenes/lenticular_card/textures.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "io/cache_file.h"
#include "render/srgb.h"
#include "scenes/common/periodic_fbm.h"
#include "sdf/det_math.h"

namespace sdfreel::lenticular_card {
namespace {

constexpr float PRINT_REFLECTANCE = 0.9f;
constexpr uint32_t RIDGE_SEED = 0x1e17c0deu;
constexpr int RIDGE_CELLS = 8, RIDGE_OCTAVES = 4;
constexpr float RIDGE_SLOPE_SCALE = 6.0f;

ShaderTexture as_shader(const std::string& name, const Texture& t) {
  return ShaderTexture{name, t.width, t.height, t.channels, t.texels};
}

}  // namespace

InterlaceLayout card_layout(int views) {
  return InterlaceLayout{views, double(views), false};
}

Texture print_texture(const StripPrint& print) {
  Texture t(print.width, print.height, 4);
  tbb::parallel_for(0, print.height, [&](int y) {
    for (int x = 0; x < print.width; ++x) {
      const glm::vec4 c = print.texel(x, y);
      std::copy_n(&c.x, 4, t.at(x, y));
    }
  });
  return t;
}

CardPrints make_card_prints(const std::vector<Rgb8Image>& a, const std::vector<Rgb8Image>& b) {
  if (a.empty() || a.size() != b.size())
    throw std::invalid_argument("lenticular_card: the two prints need the same number of views");
  const InterlaceLayout layout = card_layout(int(a.size()));
  Rgb8Image pa, pb;
  tbb::parallel_invoke([&] { pa = interlace(a, layout); }, [&] { pb = interlace(b, layout); });
  if (pa.width != pb.width || pa.height != pb.height)
    throw std::invalid_argument("lenticular_card: the two prints differ in size");
  auto print = std::make_shared<StripPrint>();
  print->width = pa.width;
  print->height = pa.height * 2;
  print->views = int(a.size());
  for (int i = 0; i < 256; ++i)
    print->decode[size_t(i)] = srgb_to_linear(float(i) / 255.0f) * PRINT_REFLECTANCE;
  CardPrints out;
  out.lenses = a[0].width;
  out.views = int(a.size());
  out.view_height = a[0].height;
  // The print's bytes, a over b, name its texels; the textures fill on threads of their own.
  tbb::parallel_invoke(
      [&] {
        std::vector<uint8_t> bytes(pa.rgb);
        bytes.insert(bytes.end(), pb.rgb.begin(), pb.rgb.end());
        out.key = checksum64(bytes.data(), bytes.size()) | 1ull;  // never 0 ("unknown")
      },
      [&] { out.ridges = std::make_shared<Texture>(make_ridge_map(RIDGE_MAP_SIZE, RIDGE_SEED)); },
      [&] {
        StripPrint& p = *print;
        p.rgbx.resize(size_t(p.width) * size_t(p.height) * 4);
        tbb::parallel_for(0, p.height, [&](int y) {
          const Rgb8Image& src = y < pa.height ? pa : pb;
          const uint8_t* from = src.at(0, y % pa.height);
          for (int x = 0; x < p.width; ++x, from += 3)
            std::copy_n(from, 3, &p.rgbx[4 * p.index(x, y)]);
        });
      });
  out.print = print;
  return out;
}

const CardPrints& default_card_prints() {
  static std::once_flag once;
  static CardPrints prints;
  std::call_once(once, [] {
    ViewSet lanterns{"lantern_festival", 16, 192, 144, 2, 4.0, 24.0, 1.0};
    ViewSet morph{"sdf_morph", 16, 192, 144, 2, 1.5, 24.0, 1.6};
    prints = make_card_prints(source_views(lanterns), source_views(morph));
  });
  return prints;
}

Texture make_ridge_map(int n, uint32_t seed) {
  Texture t(n, n, 4);
  const float step = 1.0f / float(n);
  auto height = [&](int x, int y) {
    return periodic_fbm2(float(x) * step, float(y) * step, RIDGE_CELLS * 4, RIDGE_CELLS,
                         RIDGE_OCTAVES, seed);
  };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      // Central differences on the torus: the map tiles.
      const float dx = height((x + 1) % n, y) - height((x + n - 1) % n, y);
      const float dy = height(x, (y + 1) % n) - height(x, (y + n - 1) % n);
      float* p = t.at(x, y);
      p[0] = dm::clamp(-dx * RIDGE_SLOPE_SCALE, -1.0f, 1.0f);
      p[1] = dm::clamp(-dy * RIDGE_SLOPE_SCALE, -1.0f, 1.0f);
      p[2] = 0.0f;
      p[3] = 1.0f;
    }
  return t;
}

std::vector<ShaderTexture> card_shader_textures(const CardPrints& prints) {
  return {as_shader("u_card_print", print_texture(*prints.print)),
          as_shader("u_card_ridges", *prints.ridges)};
}

}  // namespace sdfreel::lenticular_card
