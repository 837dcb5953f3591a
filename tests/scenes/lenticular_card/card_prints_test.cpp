// make_card_prints, which fills its textures on several threads, against its definition written
// out plainly: every texel of the print is its interlaced byte decoded, read through the strips or
// as GL's float texels, and the key is the checksum of the print's bytes, a over b.
#include <gtest/gtest.h>

#include <random>

#include "io/cache_file.h"
#include "render/srgb.h"
#include "render/tiling.h"
#include "scenes/lenticular_card/random_prints.h"

namespace sdfreel::lenticular_card {
namespace {

TEST(CardPrints, TexelsAndKeyAreThePlainDefinition) {
  std::mt19937 rng(7);
  std::vector<Rgb8Image> a, b;
  for (int v = 0; v < 5; ++v) {
    Rgb8Image va(23, 9), vb(23, 9);
    for (uint8_t& x : va.rgb) x = uint8_t(rng());
    for (uint8_t& x : vb.rgb) x = uint8_t(rng());
    a.push_back(va), b.push_back(vb);
  }
  const CardPrints prints = make_card_prints(a, b);
  const Rgb8Image pa = interlace(a, card_layout(5)), pb = interlace(b, card_layout(5));
  const Texture print = print_texture(*prints.print);
  ASSERT_EQ(print.width, pa.width);
  ASSERT_EQ(print.height, pa.height * 2);
  std::vector<uint8_t> bytes;
  for (int y = 0; y < print.height; ++y)
    for (int x = 0; x < print.width; ++x) {
      const uint8_t* p = y < pa.height ? pa.at(x, y) : pb.at(x, y - pa.height);
      bytes.insert(bytes.end(), p, p + 3);
      const float* t = print.at(x, y);
      const glm::vec4 s = prints.print->texel(x, y);
      for (int c = 0; c < 3; ++c) {
        const float want = srgb_to_linear(float(p[c]) / 255.0f) * 0.9f;
        ASSERT_EQ(t[c], want) << "texel " << x << ", " << y << " channel " << c;
        ASSERT_EQ(s[c], want) << "strip texel of " << x << ", " << y << " channel " << c;
      }
      ASSERT_EQ(t[3], 1.0f);
    }
  EXPECT_EQ(prints.key, checksum64(bytes.data(), bytes.size()) | 1ull);
  EXPECT_EQ(prints.lenses, 23);
  EXPECT_EQ(prints.views, 5);
  EXPECT_EQ(prints.view_height, 9);
}

TEST(CardPrints, DoNotDependOnTheThreads) {
  std::mt19937 one(3), two(3);
  CardPrints a, b;
  with_threads(1, [&] { a = random_prints(one, 4, 31, 17); });
  with_threads(2, [&] { b = random_prints(two, 4, 31, 17); });
  EXPECT_EQ(a.print->rgbx, b.print->rgbx);
  EXPECT_EQ(print_texture(*a.print).texels, print_texture(*b.print).texels);
  EXPECT_EQ(a.ridges->texels, b.ridges->texels);
  EXPECT_EQ(a.key, b.key);
}

}  // namespace
}  // namespace sdfreel::lenticular_card
