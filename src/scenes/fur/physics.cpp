#include "scenes/fur/physics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <vector>

#include "scenes/fur/spring.h"
#include "scenes/fur/strand_hash.h"
#include "scenes/fur/turning.h"
#include "sdf/det_math.h"

namespace sdfreel::fur {
namespace {

constexpr Shape SHAPES[BODY_COUNT] = {Shape::Sphere, Shape::RoundedCube, Shape::Torus};
constexpr double HOME_X[BODY_COUNT] = {-0.45, 0.0, 0.45};
constexpr double HOME_Z[BODY_COUNT] = {0.0, 0.06, -0.04};
constexpr double HOME_YAW[BODY_COUNT] = {0.0, 0.5, 0.0};
// Contacts: restitution of floor, walls and other shapes; speeds below REST_SPEED stop bouncing.
constexpr double FLOOR_BOUNCE = 0.5, WALL_BOUNCE = 0.6, BODY_BOUNCE = 0.5, REST_SPEED = 0.3;
constexpr double IMPACT_FRICTION = 0.8, IMPACT_SPIN = 0.7;
constexpr double SLIDE_DRAG = 2.5, SPIN_DRAG = 3.0;  // 1/s, while on the floor
constexpr double SLEEP_SPEED = 0.05, SLEEP_SPIN = 0.1;
// A push: this upward speed, a sideways speed in a direction hashed from (push, body), a spin
// about the vertical and a tumble about the horizontal axis across the path (rad/s at most).
constexpr double PUSH_UP = 2.2, PUSH_SIDE = 0.5, PUSH_SPIN = 10.0, PUSH_TUMBLE = 12.0;
// On the floor a tilted shape rights itself with this angular acceleration (rad/s^2) times the sine
// of its tilt; below FLAT_TILT it lies flat, and falling asleep lays it exactly so.
constexpr double RIGHTING = 60.0, FLAT_TILT = 0.02;
const glm::dvec3 UP(0.0, 1.0, 0.0);

struct Body {
  Shape shape = Shape::Sphere;
  glm::dvec3 p{0.0}, v{0.0};
  glm::dquat q{1.0, 0.0, 0.0, 0.0};  // orientation
  glm::dvec3 w{0.0};                 // angular velocity, rad/s, exhibit space
  double scale = 1.0;
  bool asleep = true, on_floor = true;
  SpringState lag[3], twist[3];
};

glm::dmat3 turn_of(const Body& b) {
  return glm::mat3_cast(b.q);
}

double extent(const Body& b, int axis) {
  return support(b.shape, b.scale, turn_of(b), axis);
}

glm::dvec3 rest_axis_of(const Body& b) {
  return rest_axis(b.shape, turn_of(b));
}

// Turned so that its rest axis points straight up.
void lay_flat(Body& b) {
  if (b.shape == Shape::Sphere) return;
  b.q = glm::normalize(flat_turn(rest_axis_of(b)) * b.q);
}

glm::dvec3 rest_lag() {
  return glm::dvec3(0.0, -GRAVITY / (SPRING_OMEGA * SPRING_OMEGA), 0.0);
}

double scale_of(Shape s, const PhysicsInputs& in, double t) {
  return s == Shape::Sphere ? sphere_scale(in, t) : 1.0;
}

// The radius of a shape's footprint on the floor, for collisions between shapes: the cube's
// widest (across its diagonal), the others' at any turn.
double footprint(const Body& b) {
  const double widest[3] = {SPHERE_RADIUS,
                            (CUBE_HALF - CUBE_ROUNDING) * 1.4142135623730951 + CUBE_ROUNDING,
                            TORUS_MAJOR + TORUS_MINOR};
  return widest[int(b.shape)] * b.scale;
}

void settle(Body& b, double t, const PhysicsInputs& in) {
  b.scale = scale_of(b.shape, in, t);
  b.p.y = extent(b, 1);
  const double x = extent(b, 0), z = extent(b, 2);
  b.p.x = std::clamp(b.p.x, -CASE_HALF_X + x, CASE_HALF_X - x);
  b.p.z = std::clamp(b.p.z, -CASE_HALF_Z + z, CASE_HALF_Z - z);
}

void push(Body& b, int push_index, int body, double strength) {
  const glm::uvec2 h = pcg2d(glm::uvec2(uint32_t(push_index), uint32_t(body)));
  const double a = double(h.x >> 8u) / 16777216.0 * 6.283185307179586;
  const double spin = double(h.y >> 8u) / 16777216.0 - 0.5;
  const double tumble = double(pcg2d(h).x >> 8u) / 16777216.0 * 2.0 - 1.0;
  b.asleep = false;
  const glm::dvec3 side(double(dm::cos(float(a))), 0.0, double(dm::sin(float(a))));
  b.v += strength * glm::dvec3(PUSH_SIDE * side.x, PUSH_UP, PUSH_SIDE * side.z);
  // Struck off its centre it tumbles forwards or backwards about the axis across its path.
  b.w +=
      strength * (PUSH_SPIN * spin * UP + PUSH_TUMBLE * tumble * glm::dvec3(side.z, 0.0, -side.x));
}

void wall(double& p, double& v, double limit) {
  if (p > limit) {
    p = limit;
    if (v > 0.0) v = -WALL_BOUNCE * v;
  } else if (p < -limit) {
    p = -limit;
    if (v < 0.0) v = -WALL_BOUNCE * v;
  }
}

void move(Body& b, double t_next, const PhysicsInputs& in, double slide, double spin_drag) {
  b.scale = scale_of(b.shape, in, t_next);
  if (b.asleep) return settle(b, t_next, in);
  b.v.y -= GRAVITY * DT;
  b.p += b.v * DT;
  const double speed = std::sqrt(glm::dot(b.w, b.w));
  if (speed > 0.0) b.q = glm::normalize(rotation_about(b.w / speed, speed * DT) * b.q);
  const double down = extent(b, 1);
  b.on_floor = b.p.y <= down;
  if (b.on_floor) {
    b.p.y = down;
    if (b.v.y < -REST_SPEED) {
      b.v.y = -FLOOR_BOUNCE * b.v.y;
      b.v.x *= IMPACT_FRICTION, b.v.z *= IMPACT_FRICTION, b.w *= IMPACT_SPIN;
    } else {
      b.v.y = std::max(b.v.y, 0.0);
    }
    b.v.x *= slide, b.v.z *= slide, b.w *= spin_drag;
    b.w += (RIGHTING * DT) * glm::cross(rest_axis_of(b), UP);  // a tilted shape rights itself
  }
  if (b.p.y > CASE_HEIGHT - down) b.p.y = CASE_HEIGHT - down, b.v.y = -std::fabs(b.v.y);
  wall(b.p.x, b.v.x, CASE_HALF_X - extent(b, 0));
  wall(b.p.z, b.v.z, CASE_HALF_Z - extent(b, 2));
}

// Shapes meet as discs on the floor plane (when their heights overlap): pushed apart, and their
// approach speed along the line between them reversed with restitution. A sleeper that is hit
// wakes.
void collide(Body& a, Body& b) {
  const glm::dvec2 d(b.p.x - a.p.x, b.p.z - a.p.z);
  const double reach = footprint(a) + footprint(b);
  const double dist = std::sqrt(d.x * d.x + d.y * d.y);
  const double tall = extent(a, 1) + extent(b, 1);
  if (dist >= reach || dist == 0.0 || std::fabs(b.p.y - a.p.y) >= tall) return;
  const glm::dvec2 n = d / dist;
  const double half = 0.5 * (reach - dist);
  a.p.x -= n.x * half, a.p.z -= n.y * half;
  b.p.x += n.x * half, b.p.z += n.y * half;
  const double approach = (b.v.x - a.v.x) * n.x + (b.v.z - a.v.z) * n.y;
  if (approach >= 0.0) return;
  const double j = -0.5 * (1.0 + BODY_BOUNCE) * approach;
  a.v.x -= j * n.x, a.v.z -= j * n.y;
  b.v.x += j * n.x, b.v.z += j * n.y;
  a.asleep = b.asleep = false;
}

struct Simulation {
  explicit Simulation(const PhysicsInputs& inputs) : in(inputs) {}
  const PhysicsInputs& in;
  SpringCoefficients spring = spring_coefficients(SPRING_OMEGA, SPRING_ZETA, DT);
  double slide = series_exp(-SLIDE_DRAG * DT), spin_drag = series_exp(-SPIN_DRAG * DT);
  std::vector<Body> bodies;

  // One step from t to t + DT; `since_push` seconds after the last push at t + DT.
  void step(double t, double since_push) {
    std::vector<Body> before = bodies;
    for (Body& b : bodies) move(b, t + DT, in, slide, spin_drag);
    for (int i = 0; i < BODY_COUNT; ++i)
      for (int j = i + 1; j < BODY_COUNT; ++j) collide(bodies[size_t(i)], bodies[size_t(j)]);
    for (size_t i = 0; i < bodies.size(); ++i) {
      Body& b = bodies[i];
      const bool slow = glm::length(b.v) < SLEEP_SPEED && glm::length(b.w) < SLEEP_SPIN;
      const bool flat = glm::length(glm::cross(rest_axis_of(b), UP)) < FLAT_TILT;
      if (!b.asleep && ((b.on_floor && slow && flat) || since_push >= SLEEP_AFTER)) {
        b.asleep = true;
        b.v = glm::dvec3(0.0), b.w = glm::dvec3(0.0);
        lay_flat(b);
        settle(b, t + DT, in);
      }
      // The fur's drive: gravity minus the body's acceleration over this step.
      const glm::dvec3 accel = (b.v - before[i].v) / DT;
      const glm::dvec3 goal =
          (glm::dvec3(0.0, -GRAVITY, 0.0) - accel) / (SPRING_OMEGA * SPRING_OMEGA);
      for (int c = 0; c < 3; ++c) b.lag[c] = spring_step(spring, b.lag[c], goal[c]);
      const glm::dvec3 alpha = (b.w - before[i].w) / DT;
      for (int c = 0; c < 3; ++c)
        b.twist[c] = spring_step(spring, b.twist[c], -alpha[c] / (SPRING_OMEGA * SPRING_OMEGA));
      if (since_push >= SETTLE_AFTER) snap(b);
    }
  }

  static void snap(Body& b) {
    const glm::dvec3 rest = rest_lag();
    for (int c = 0; c < 3; ++c) b.lag[c] = {rest[c], 0.0}, b.twist[c] = {};
  }

  bool quiet() const {
    const glm::dvec3 rest = rest_lag();
    for (const Body& b : bodies) {
      if (!b.asleep) return false;
      for (int c = 0; c < 3; ++c)
        if (b.lag[c].x != rest[c] || b.lag[c].v != 0.0 || b.twist[c].x != 0.0 ||
            b.twist[c].v != 0.0)
          return false;
    }
    return true;
  }
};

std::vector<Body> rest_bodies(const PhysicsInputs& in, double t) {
  std::vector<Body> out;
  const glm::dvec3 lag = rest_lag();
  for (int i = 0; i < BODY_COUNT; ++i) {
    Body b;
    b.shape = SHAPES[i];
    b.p = glm::dvec3(HOME_X[i], 0.0, HOME_Z[i]);
    b.q = rotation_about(UP, HOME_YAW[i]);
    for (int c = 0; c < 3; ++c) b.lag[c] = {lag[c], 0.0};
    settle(b, t, in);
    out.push_back(b);
  }
  return out;
}

ExhibitPose blend(const std::vector<Body>& a, const std::vector<Body>& b, double f,
                  const PhysicsInputs& in, double t) {
  ExhibitPose out;
  for (int i = 0; i < BODY_COUNT; ++i) {
    const Body& x = a[size_t(i)];
    const Body& y = b[size_t(i)];
    BodyPose& p = out[size_t(i)];
    p.shape = x.shape;
    p.position = x.p + (y.p - x.p) * f;
    // Between the two steps' orientations: the normalised blend of the nearer pair of quaternions.
    const glm::dquat qy = glm::dot(x.q, y.q) < 0.0 ? -y.q : y.q;
    p.turn = glm::mat3_cast(glm::normalize(x.q + (qy - x.q) * f));
    p.scale = scale_of(x.shape, in, t);
    for (int c = 0; c < 3; ++c) {
      p.fur_lag[c] = x.lag[c].x + (y.lag[c].x - x.lag[c].x) * f;
      p.fur_twist[c] = x.twist[c].x + (y.twist[c].x - x.twist[c].x) * f;
    }
    if (x.asleep && y.asleep) {  // resting shapes follow the sphere's size exactly
      Body rest = x;
      settle(rest, t, in);
      p.position = rest.p;
    }
  }
  return out;
}

}  // namespace

double sphere_scale(const PhysicsInputs& in, double t) {
  const float phase = dm::wrap_phase(t, in.grow_period) / float(in.grow_period);
  return 1.0 + in.grow_amount * double(dm::sin(dm::TWO_PI * phase));
}

ExhibitPose rest_pose(const PhysicsInputs& in, double t) {
  const std::vector<Body> b = rest_bodies(in, t);
  return blend(b, b, 0.0, in, t);
}

ExhibitPose exhibit_pose(const PhysicsInputs& in, double t, int64_t* steps) {
  std::vector<double> pushes;
  for (double p : in.push_times)
    if (p >= 0.0 && std::isfinite(p)) pushes.push_back(p);
  std::sort(pushes.begin(), pushes.end());
  if (steps) *steps = 0;
  if (pushes.empty() || !(t >= pushes[0])) return rest_pose(in, t);
  const double t0 = pushes[0];
  std::vector<int64_t> push_steps;
  for (double p : pushes) push_steps.push_back(int64_t(std::ceil((p - t0) / DT)));
  const double span = (t - t0) / DT;
  const int64_t last = int64_t(std::floor(span));
  const double f = span - double(last);

  Simulation sim(in);
  sim.bodies = rest_bodies(in, t0);
  size_t next_push = 0;
  int64_t last_push_step = 0, count = 0;
  auto advance = [&](int64_t n) {
    ++count;
    for (; next_push < push_steps.size() && push_steps[next_push] == n; ++next_push) {
      for (int b = 0; b < BODY_COUNT; ++b)
        push(sim.bodies[size_t(b)], int(next_push), b, in.push_strength);
      last_push_step = n;
    }
    sim.step(t0 + double(n) * DT, double(n + 1 - last_push_step) * DT);
  };
  for (int64_t n = 0; n < last;) {
    const int64_t upcoming = next_push < push_steps.size() ? push_steps[next_push] : last;
    if (upcoming > n && sim.quiet()) {  // nothing moves until the next push
      n = std::min(upcoming, last);
      continue;
    }
    advance(n++);
  }
  const std::vector<Body> at_last = sim.bodies;
  advance(last);
  if (steps) *steps = count;
  return blend(at_last, sim.bodies, f, in, t);
}

}  // namespace sdfreel::fur
