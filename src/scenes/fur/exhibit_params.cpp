#include "scenes/fur/exhibit_params.h"

#include <utility>

namespace sdfreel::fur {
namespace {

ParamSpec scalar_param(const std::string& name, double def, double min, double max,
                       const char* doc) {
  return ParamSpec{name, 1, {def}, min, max, doc};
}

ParamSpec vector_param(const std::string& name, std::vector<double> def, double min, double max,
                       const char* doc) {
  return ParamSpec{name, 3, std::move(def), min, max, doc};
}

ParamSpec colour_param(const std::string& name, std::vector<double> def, const char* doc) {
  return ParamSpec{name, 3, std::move(def), 0.0, 1.0, doc};
}

}  // namespace

std::array<FurLook, BODY_COUNT> ExhibitParams::default_looks() {
  FurLook sphere;  // long, shaggy, brown
  sphere.length = 0.07, sphere.density = 90.0, sphere.thickness = 1.6, sphere.curvature = 1.0;
  sphere.base_color = {0.09, 0.045, 0.02}, sphere.tip_color = {0.78, 0.56, 0.34};
  sphere.shells = 24.0;
  FurLook cube;  // short, dense, blue velvet
  cube.length = 0.025, cube.density = 70.0, cube.thickness = 1.9, cube.curvature = 0.3;
  cube.base_color = {0.02, 0.05, 0.12}, cube.tip_color = {0.35, 0.62, 0.95};
  cube.shells = 16.0;
  FurLook torus;  // soft, floppy, pink
  torus.length = 0.045, torus.density = 80.0, torus.thickness = 2.2, torus.curvature = 3.0;
  torus.base_color = {0.2, 0.03, 0.08}, torus.tip_color = {0.97, 0.62, 0.76};
  torus.shells = 32.0;
  return {sphere, cube, torus};
}

std::vector<ParamSpec> exhibit_param_specs(const std::string& prefix) {
  const ExhibitParams d;
  std::vector<ParamSpec> out;
  for (int i = 0; i < BODY_COUNT; ++i) {
    const std::string p = prefix + FUR_PREFIXES[i] + "_";
    const FurLook& l = d.looks[size_t(i)];
    out.push_back(scalar_param(p + "length", l.length, 0.0, 0.3,
                               "fur length: extrusion of the outermost shell, metres"));
    out.push_back(scalar_param(p + "density", l.density, 1.0, 2000.0,
                               "strands per UV unit (one strand per cell of the UV grid)"));
    out.push_back(scalar_param(p + "thickness", l.thickness, 0.0, 10.0,
                               "strand radius at the root, in half cells; strands taper to 0"));
    out.push_back(scalar_param(p + "curvature", l.curvature, 0.0, 8.0,
                               "bend: shell i follows the motion by (i/N)^(1 + curvature)"));
    out.push_back(colour_param(p + "base_color", {l.base_color.x, l.base_color.y, l.base_color.z},
                               "fur colour at the roots, linear Rec.709"));
    out.push_back(colour_param(p + "tip_color", {l.tip_color.x, l.tip_color.y, l.tip_color.z},
                               "fur colour at the tips, linear Rec.709"));
    out.push_back(scalar_param(p + "shells", l.shells, 1.0, 256.0,
                               "shell count N (rounded to an integer); more = finer strands"));
  }
  const PhysicsInputs& ph = d.physics;
  out.push_back(vector_param(prefix + "push_times",
                             {ph.push_times[0], ph.push_times[1], ph.push_times[2]}, -1.0, 1e7,
                             "TIME of up to three pushes that make the shapes jump; negative = "
                             "none (key with step interpolation to schedule them)"));
  out.push_back(scalar_param(prefix + "push_strength", ph.push_strength, 0.0, 3.0,
                             "scale of the pushes' speeds (1: about 30 cm high)"));
  out.push_back(scalar_param(prefix + "grow_amount", ph.grow_amount, 0.0, 0.5,
                             "the sphere grows and shrinks by this fraction of its size"));
  out.push_back(scalar_param(prefix + "grow_period", ph.grow_period, 0.5, 600.0,
                             "seconds for the sphere to grow and shrink once"));
  out.push_back(scalar_param(prefix + "displacement_strength", d.displacement_strength, 0.0, 2.0,
                             "how far the fur tips follow the spring's lag (0: stiff fur)"));
  out.push_back(scalar_param(prefix + "light_intensity", d.light_intensity, 0.0, 10.0,
                             "intensity of the key light"));
  return out;
}

ExhibitParams read_exhibit_params(const ParamValues& v, const std::string& prefix) {
  ExhibitParams e;
  for (int i = 0; i < BODY_COUNT; ++i) {
    const std::string p = prefix + FUR_PREFIXES[i] + "_";
    FurLook& l = e.looks[size_t(i)];
    l.length = v.scalar(p + "length");
    l.density = v.scalar(p + "density");
    l.thickness = v.scalar(p + "thickness");
    l.curvature = v.scalar(p + "curvature");
    l.base_color = glm::dvec3(v.vec3(p + "base_color"));
    l.tip_color = glm::dvec3(v.vec3(p + "tip_color"));
    l.shells = v.scalar(p + "shells");
  }
  const std::vector<double>& pushes = v.raw(prefix + "push_times");
  for (size_t i = 0; i < 3; ++i) e.physics.push_times[i] = pushes[i];
  e.physics.push_strength = v.scalar(prefix + "push_strength");
  e.physics.grow_amount = v.scalar(prefix + "grow_amount");
  e.physics.grow_period = v.scalar(prefix + "grow_period");
  e.displacement_strength = v.scalar(prefix + "displacement_strength");
  e.light_intensity = v.scalar(prefix + "light_intensity");
  return e;
}

}  // namespace sdfreel::fur
