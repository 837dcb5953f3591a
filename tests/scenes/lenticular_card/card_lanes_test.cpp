// shadeCard_lanes against shadeCard lane by lane: the same hits, colours and distances to the bit,
// for rays from every side (the face at any angle, the edges, the stand, behind, along the axes,
// grazing, straight down), under a turned and scaled model, through the print and its strip copy.
#include "scenes/lenticular_card/card_lanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "scenes/lenticular_card/card.h"
#include "scenes/lenticular_card/exhibit.h"
#include "scenes/lenticular_card/random_prints.h"
#include "scenes/lenticular_card/textures.h"

namespace sdfreel::lenticular_card {
namespace {

// A direction toward `at` from a random side, sometimes exactly along an axis (parallel slabs).
glm::vec3 direction(std::mt19937& rng, const glm::vec3& from, const glm::vec3& at) {
  std::uniform_int_distribution<int> kind(0, 9);
  switch (kind(rng)) {
    case 0:
      return glm::vec3(0.0f, 0.0f, from.z > at.z ? -1.0f : 1.0f);
    case 1:
      return glm::vec3(0.0f, -1.0f, 0.0f);
    case 2:
      return glm::vec3(from.x > at.x ? -1.0f : 1.0f, 0.0f, 0.0f);
    default:
      return glm::normalize(at - from);
  }
}

TEST(CardLanes, EachLaneIsShadeCardsRay) {
  std::mt19937 rng(29);
  const CardPrints prints = random_prints(rng, 6, 11, 7);
  const Texture plain = print_texture(*prints.print);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const glm::mat4 turned =
      glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), {0.3f, 0.9f, -2.0f}), 0.7f,
                             glm::vec3(0.2f, 1.0f, 0.1f)),
                 glm::vec3(1.3f));
  int hits = 0, fronts = 0, packets = 0;
  for (const glm::mat4& model : {glm::mat4(1.0f), turned})
    for (const bool strips : {false, true})
      for (double time : {0.0, 4.4, 1e6}) {
        const CardUniforms u = card_uniforms(model, prints, CardLook{}, time);
        const CardTextures tex = strips ? CardTextures{prints.print.get(), prints.ridges.get()}
                                        : CardTextures{nullptr, prints.ridges.get(), &plain};
        for (int p = 0; p < 600; ++p, ++packets) {
          // One eye a packet (primary rays share it); eight targets on or around the card.
          const glm::vec3 eye_local(unit(rng) * 1.5f, 0.3f + unit(rng), unit(rng) * 1.5f);
          const glm::vec3 eye = glm::vec3(model * glm::vec4(eye_local, 1.0f));
          RayPacket rays{eye, V3x8(), 1e-3f};
          for (int i = 0; i < LANES; ++i) {
            const glm::vec3 at_local(unit(rng) * 0.4f, 0.3f + unit(rng) * 0.35f, unit(rng) * 0.1f);
            const glm::vec3 at = glm::vec3(model * glm::vec4(at_local, 1.0f));
            rays.dir.set_lane(i, direction(rng, eye, at));
          }
          V3x8 colour;
          F8 t;
          const M8 hit = shadeCard_lanes(rays, u, tex, colour, t);
          for (int i = 0; i < LANES; ++i) {
            glm::vec3 c(0.0f);
            float ts = 0.0f;
            const bool h = shadeCard(rays.ray(i), u, tex, c, ts);
            ASSERT_EQ(lane(hit, i), h) << "packet " << packets << " lane " << i;
            if (!h) continue;
            ++hits;
            const glm::vec3 d = to_local_direction(u.world_to_local, rays.dir.lane(i));
            const glm::vec3 at = to_local_point(u.world_to_local, eye) + d * ts;
            fronts += d.z < 0.0f && std::abs(at.z - CARD_HALF_THICKNESS) < 1e-4f &&
                      at.y > CARD_CENTRE_Y - CARD_HALF_HEIGHT + 1e-3f;
            const glm::vec3 cl = colour.lane(i);
            EXPECT_EQ(0, std::memcmp(&cl, &c, sizeof c)) << "packet " << packets << " lane " << i;
            EXPECT_EQ(0, std::memcmp(&t[i], &ts, sizeof ts)) << "packet " << packets;
          }
        }
      }
  // The rays reach every part: many hits (card face, edges, stand), of all 57,600 lanes, and
  // thousands of them the glossy face.
  EXPECT_GT(hits, 10000);
  EXPECT_GT(fronts, 3000);
  EXPECT_LT(fronts, hits);
}

}  // namespace
}  // namespace sdfreel::lenticular_card
