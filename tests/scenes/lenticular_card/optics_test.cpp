// The card's lenses behave as the lens formula says: with two views (black and white) the card
// switches at the angles sin(theta) = n sin(atan(b / (N e))) predicts (computed here in double,
// apart from the float shading path), the card seen edge-on or from behind stays finite and
// clean, and the scroll offset holds and slides as documented, also at TIME 1e6.
#include "scenes/lenticular_card/optics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scenes/lenticular_card/card.h"
#include "scenes/lenticular_card/exhibit.h"

namespace sdfreel::lenticular_card {
namespace {

constexpr double DEG = 3.14159265358979323846 / 180.0;
constexpr int LENSES = 4;

Rgb8Image flat_view(uint8_t grey) {
  Rgb8Image v(LENSES, 2);
  for (uint8_t& b : v.rgb) b = grey;
  return v;
}

// Two prints, each two views: view 0 black, view 1 white.
CardPrints black_and_white() {
  const std::vector<Rgb8Image> views = {flat_view(0), flat_view(255)};
  return make_card_prints(views, views);
}

CardUniforms flat_look(const CardPrints& prints) {
  CardLook look;
  look.gloss = 0.0f;  // the print alone
  return card_uniforms(glm::mat4(1.0f), prints, look, 0.0);
}

// The brightness of the card's front at the centre of lens 2 (x = 0.08), seen from angle theta
// (degrees, positive toward +x) in the plane across the lenses.
float seen_brightness(double theta_deg, const CardUniforms& u, const CardPrints& prints) {
  const glm::vec3 target(0.08f, CARD_CENTRE_Y, CARD_HALF_THICKNESS);
  const glm::vec3 toward(float(std::sin(theta_deg * DEG)), 0.0f, float(std::cos(theta_deg * DEG)));
  const Ray ray{target + toward * 2.0f, -toward, 1e-3f};
  glm::vec3 colour(0.0f);
  float t = 0.0f;
  EXPECT_TRUE(shadeCard(ray, u, CardTextures{prints.print.get(), prints.ridges.get()}, colour, t));
  return colour.x;
}

TEST(LenticularOptics, TwoViewsSwitchWhereTheLensFormulaSays) {
  const CardPrints prints = black_and_white();
  const CardUniforms u = flat_look(prints);
  const float white = seen_brightness(1.0, u, prints), black = seen_brightness(-1.0, u, prints);
  ASSERT_GT(white, 0.3f) << "just right of the normal the white view shows";
  ASSERT_EQ(black, 0.0f) << "just left of it the black one";
  int switches = 0;
  for (int b = -3; b <= 3; ++b) {
    const double t = double(b) / (2.0 * double(u.thickness));
    const double s = u.ior * t / std::sqrt(1.0 + t * t);
    if (std::abs(s) >= 0.999) continue;  // beyond grazing
    const double angle = switch_angle_deg(b, 2, u.ior, u.thickness);
    const float before = seen_brightness(angle - 0.3, u, prints);
    const float after = seen_brightness(angle + 0.3, u, prints);
    // Turning toward +x moves the seen point toward -x, through strips 1, 0, 1, ...: from the
    // right of boundary b the white view (1) shows when b is even.
    const bool white_after = b % 2 == 0;
    // Black prints 0 exactly; white is dimmed only by the sheet's Fresnel transmission.
    EXPECT_EQ(after > 0.25f * white, white_after) << "boundary " << b << " at " << angle << " deg";
    EXPECT_EQ(before > 0.25f * white, !white_after) << "boundary " << b << " at " << angle;
    EXPECT_EQ(white_after ? before : after, 0.0f) << "boundary " << b;
    ++switches;
  }
  EXPECT_EQ(switches, 5);  // b = -2 .. 2: the flip zones within +-60 degrees
}

TEST(LenticularOptics, SeenViewMatchesTheFormulaOverAllAngles) {
  for (double a = -80.0; a <= 80.0; a += 0.37) {
    const double t = std::tan(std::asin(std::sin(a * DEG) / 1.56));
    const double x = 0.5 - 1.5 * t;
    const int strip = int(std::floor(x * 16.0)) % 16;
    const int expected = 15 - (strip + 16) % 16;
    EXPECT_EQ(seen_view(float(std::sin(a * DEG)), 1.56f, 1.5f, 16), expected) << a << " deg";
  }
}

TEST(LenticularOptics, EdgeOnGrazingAndBehindStayFiniteAndClean) {
  const CardPrints prints = black_and_white();
  CardLook look;
  const CardUniforms u = card_uniforms(glm::mat4(1.0f), prints, look, 0.0);
  const CardTextures tex{prints.print.get(), prints.ridges.get()};
  int hits = 0;
  for (int i = 0; i <= 400; ++i) {
    // Around the card at its centre height, including exactly edge-on (z = 0 plane) rays.
    const double a = (i / 400.0) * 360.0 * DEG;
    const glm::vec3 toward(float(std::sin(a)), 0.0f, float(std::cos(a)));
    for (float y : {CARD_CENTRE_Y, CARD_CENTRE_Y + CARD_HALF_HEIGHT * 0.99f}) {
      const Ray ray{glm::vec3(0.01f, y, 0.0f) + toward * 2.0f, -toward, 1e-3f};
      glm::vec3 c(-1.0f);
      float t = -1.0f;
      if (!shadeCard(ray, u, tex, c, t)) continue;
      ++hits;
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(std::isfinite(c[k])) << "angle " << a / DEG;
        EXPECT_GE(c[k], 0.0f);
        EXPECT_LT(c[k], 4.0f);
      }
      EXPECT_TRUE(std::isfinite(t) && t > 0.0f);
    }
  }
  EXPECT_GT(hits, 700);
  // Straight down onto the card's top edge (no direction across the lenses at all).
  glm::vec3 c;
  float t;
  ASSERT_TRUE(shadeCard(Ray{glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f), 1e-3f}, u,
                        tex, c, t));
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
  EXPECT_FLOAT_EQ(t, 2.0f - (CARD_CENTRE_Y + CARD_HALF_HEIGHT));
}

TEST(LenticularOptics, ScrollHoldsThenSlidesAndKeepsItsPhaseAtTime1e6) {
  EXPECT_EQ(scroll_offset(0.0, 6.0, 0.7), 0.0);
  EXPECT_EQ(scroll_offset(4.1, 6.0, 0.7), 0.0);            // holding print A
  EXPECT_NEAR(scroll_offset(5.1, 6.0, 0.7), 0.5, 1e-12);   // halfway through the slide
  EXPECT_NEAR(scroll_offset(6.5, 6.0, 0.7), 1.0, 1e-12);   // holding print B
  EXPECT_NEAR(scroll_offset(12.5, 6.0, 0.7), 0.0, 1e-12);  // back to A
  EXPECT_NEAR(scroll_offset(1e6 + 0.5, 6.0, 0.7), scroll_offset(4.0 + 0.5, 6.0, 0.7), 1e-6);
}

}  // namespace
}  // namespace sdfreel::lenticular_card
