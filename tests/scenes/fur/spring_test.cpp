// The fur spring: fixed steps of the exact update follow the closed-form step response to 1e-9
// (double), whatever the step, and the power series behind its coefficients match libm.
#include "scenes/fur/spring.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scenes/fur/physics.h"

namespace sdfreel::fur {
namespace {

// x(0) = 1, v(0) = 0, goal 0: x(t) = e^(-zeta w t) (cos(wd t) + zeta w / wd sin(wd t)).
double step_response(double omega, double zeta, double t) {
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);
  return std::exp(-zeta * omega * t) * (std::cos(wd * t) + zeta * omega / wd * std::sin(wd * t));
}

TEST(FurSpring, FixedStepsFollowTheClosedFormStepResponse) {
  for (double dt : {DT, 1.0 / 60.0, 0.1}) {
    const SpringCoefficients c = spring_coefficients(SPRING_OMEGA, SPRING_ZETA, dt);
    SpringState s{1.0, 0.0};
    double worst = 0.0;
    for (int n = 1; n * dt <= 3.0; ++n) {
      s = spring_step(c, s, 0.0);
      worst = std::max(worst, std::fabs(s.x - step_response(SPRING_OMEGA, SPRING_ZETA, n * dt)));
    }
    EXPECT_LT(worst, 1e-9) << "dt " << dt;
  }
}

TEST(FurSpring, AConstantGoalIsReachedWithoutOvershootBias) {
  const SpringCoefficients c = spring_coefficients(SPRING_OMEGA, SPRING_ZETA, DT);
  SpringState s{0.0, 0.0};
  for (int n = 0; n < int(SETTLE_AFTER / DT); ++n) s = spring_step(c, s, -0.04);
  EXPECT_NEAR(s.x, -0.04, 1e-9);
  EXPECT_NEAR(s.v, 0.0, 1e-8);
}

TEST(FurSpring, SeriesMatchLibm) {
  for (double x = -2.0; x <= 2.0; x += 0.01) {
    EXPECT_NEAR(series_exp(x), std::exp(x), 4e-15 * std::exp(x)) << x;
    EXPECT_NEAR(series_cos(x), std::cos(x), 2e-15) << x;
    EXPECT_NEAR(series_sin(x), std::sin(x), 2e-15) << x;
  }
}

}  // namespace
}  // namespace sdfreel::fur
