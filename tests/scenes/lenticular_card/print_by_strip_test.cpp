// The CPU reads the card's print strip by strip, as bytes (textures.h, StripPrint): every texel
// lands where the layout says, and the card's shading through the strips gives the same bits as
// through the plain float print GL reads, at every angle, lens, row and scroll.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "scenes/lenticular_card/card.h"
#include "scenes/lenticular_card/exhibit.h"
#include "scenes/lenticular_card/random_prints.h"
#include "scenes/lenticular_card/textures.h"

namespace sdfreel::lenticular_card {
namespace {

TEST(PrintByStrip, EveryTexelMovesToItsStrip) {
  constexpr int VIEWS = 3, LENSES = 5, H = 4;
  std::mt19937 rng(2);
  const CardPrints prints = random_prints(rng, VIEWS, LENSES, H);
  const StripPrint& p = *prints.print;
  ASSERT_EQ(p.width, LENSES * VIEWS);
  ASSERT_EQ(p.height, 2 * H);
  ASSERT_EQ(p.rgbx.size(), size_t(LENSES * VIEWS * 2 * H * 4));
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      // Strip x % VIEWS of lens x / VIEWS: column x / VIEWS, row (x % VIEWS) * height + y.
      const uint8_t* c = &p.rgbx[4 * size_t(((x % VIEWS) * p.height + y) * LENSES + x / VIEWS)];
      const glm::vec4 t = p.texel(x, y);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(t[k], p.decode[c[k]]) << x << ", " << y;
    }
}

TEST(PrintByStrip, CardShadingGivesTheSameBitsAsThroughThePrint) {
  std::mt19937 rng(11);
  const CardPrints prints = random_prints(rng, 7, 9, 5);
  const Texture texels = print_texture(*prints.print);
  const CardTextures plain{nullptr, prints.ridges.get(), &texels};
  const CardTextures strips{prints.print.get(), prints.ridges.get()};
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int fronts = 0;
  for (double time : {0.0, 3.3, 7.9, 1e6}) {
    const CardUniforms u = card_uniforms(glm::mat4(1.0f), prints, CardLook{}, time);
    for (int i = 0; i < 4000; ++i) {
      // Points over the card's face (and past its sides), seen from in front at any angle.
      const glm::vec3 at(unit(rng) * CARD_HALF_WIDTH * 1.1f,
                         CARD_CENTRE_Y + unit(rng) * CARD_HALF_HEIGHT, CARD_HALF_THICKNESS);
      const glm::vec3 from =
          at + glm::normalize(glm::vec3(unit(rng), unit(rng) * 0.5f, 0.05f + std::abs(unit(rng))));
      const Ray ray{from, glm::normalize(at - from), 1e-3f};
      glm::vec3 c0(0.0f), c1(0.0f);
      float t0 = 0.0f, t1 = 0.0f;
      const bool hit = shadeCard(ray, u, plain, c0, t0);
      ASSERT_EQ(hit, shadeCard(ray, u, strips, c1, t1));
      fronts += hit;
      EXPECT_EQ(0, std::memcmp(&c0, &c1, sizeof c0)) << "ray " << i << " at time " << time;
      EXPECT_EQ(0, std::memcmp(&t0, &t1, sizeof t0));
    }
  }
  EXPECT_GT(fronts, 12000);
}

}  // namespace
}  // namespace sdfreel::lenticular_card
