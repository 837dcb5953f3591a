#pragma once
// Card prints of random views, for tests that hold two ways of shading the card to the same bits.
#include <cstdint>
#include <random>
#include <vector>

#include "scenes/lenticular_card/textures.h"

namespace sdfreel::lenticular_card {

// Two prints of `views` random views of width x height each.
inline CardPrints random_prints(std::mt19937& rng, int views, int width, int height) {
  std::vector<Rgb8Image> a, b;
  for (int v = 0; v < views; ++v) {
    Rgb8Image va(width, height), vb(width, height);
    for (uint8_t& x : va.rgb) x = uint8_t(rng());
    for (uint8_t& x : vb.rgb) x = uint8_t(rng());
    a.push_back(va), b.push_back(vb);
  }
  return make_card_prints(a, b);
}

}  // namespace sdfreel::lenticular_card
