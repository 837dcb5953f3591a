#pragma once
// The damped spring the fur rides on, integrated exactly over fixed steps (double):
//   x'' + 2 zeta omega x' + omega^2 (x - goal) = 0,
// with the goal held constant over each step. For zeta < 1 the step from (x0, v0), y0 = x0 - goal,
// is the closed form
//   y(dt) = e^(-zeta omega dt) (y0 cos(wd dt) + (v0 + zeta omega y0) / wd sin(wd dt))
//   v(dt) = e^(-zeta omega dt) (v0 cos(wd dt) - (zeta omega v0 + omega^2 y0) / wd sin(wd dt))
// with wd = omega sqrt(1 - zeta^2), so the result does not depend on the step size when the goal
// is constant (Holden, "Spring-It-On"). The per-step factors are computed once from power series
// (+ and * only), so every machine gets the same bits.
namespace sdfreel::fur {

struct SpringCoefficients {
  double omega = 0.0, zeta = 0.0, dt = 0.0;
  double decay = 0.0, cos_wd = 0.0, sin_wd_over_wd = 0.0, wd = 0.0;
};

// zeta in (0, 1), omega > 0, dt > 0 and small enough that zeta * omega * dt and wd * dt are
// below 2 (the series converge fast there).
SpringCoefficients spring_coefficients(double omega, double zeta, double dt);

struct SpringState {
  double x = 0.0, v = 0.0;
};

inline SpringState spring_step(const SpringCoefficients& c, const SpringState& s, double goal) {
  const double y0 = s.x - goal;
  const double zw = c.zeta * c.omega;
  SpringState out;
  out.x = goal + c.decay * (y0 * c.cos_wd + (s.v + zw * y0) * c.sin_wd_over_wd);
  out.v = c.decay * (s.v * c.cos_wd - (zw * s.v + c.omega * c.omega * y0) * c.sin_wd_over_wd);
  return out;
}

// Power series, exact to double rounding for |x| < 2: exp(x), cos(x), sin(x).
double series_exp(double x);
double series_cos(double x);
double series_sin(double x);

}  // namespace sdfreel::fur
