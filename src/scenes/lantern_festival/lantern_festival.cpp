// The lantern_festival scene (seed 000): its parameters, each documented where it is declared,
// its test poses and its SceneInfo. The scene itself: scene.h.
#include "scenes/common/param.h"
#include "scenes/lantern_festival/scene.h"

namespace sdfreel {

namespace lantern_festival {

std::vector<ParamSpec> lantern_festival_params() {
  return {
      scalar_param(
          "wave_amplitude", 0.15, 0.0, 0.5,
          "amplitude of the lake's largest wave (m); the four others follow the seed's 0.6 ratios"),
      scalar_param("wave_speed", 2.5, 0.0, 20.0,
                   "wave phase speed, radians per second of TIME (seed: 2.5)"),
      scalar_param("flicker_strength", 1.0, 0.0, 2.0,
                   "candle flicker depth: 0 steady, 1 the seed's flicker"),
      scalar_param("flicker_speed", 1.0, 0.0, 10.0, "candle flicker rate, 1 = the seed's"),
      scalar_param("grid_size", 8.0, 2.0, 100.0,
                   "lantern spacing (m); raised to a lantern's width where smaller, so lanterns "
                   "never overlap"),
      scalar_param("lantern_jitter", 1.0, 0.0, 1.0,
                   "how far lanterns stray from the regular grid, as a share of the free room in "
                   "their cell"),
      scalar_param("lantern_scale", 1.0, 0.25, 3.0,
                   "lantern size, 1 = the seed's (about 2 m tall)"),
      scalar_param("candle_intensity", 1.6, 0.0, 20.0, "candle light strength (1/d^2 falloff)"),
      colour_param("candle_color", {1.0, 0.45, 0.12}, "candle light colour (linear Rec.709)"),
      colour_param("paper_color", {1.0, 0.78, 0.55}, "paper albedo (linear Rec.709)"),
      scalar_param("moon_intensity", 0.25, 0.0, 5.0,
                   "moonlight strength (directional light and disc)"),
      colour_param("moon_color", {0.70, 0.80, 1.0}, "moonlight colour (linear Rec.709)"),
      scalar_param("moon_elevation", 14.0, 0.0, 90.0, "moon height above the horizon (degrees)"),
      scalar_param("moon_azimuth", 8.0, -180.0, 180.0,
                   "moon direction (degrees from +Z towards +X)"),
      colour_param("water_color", {0.003, 0.006, 0.010},
                   "water's own colour under the reflections"),
      scalar_param("water_reflection_strength", 0.7, 0.0, 1.0,
                   "share of sky and lanterns the lake reflects"),
      colour_param("fog_color", {0.030, 0.042, 0.075},
                   "fog colour at the horizon (linear Rec.709)"),
      scalar_param("fog_density", 0.006, 0.0, 1.0, "distance fog on lanterns and water, per metre"),
      scalar_param("horizon_fog", 1.0, 0.0, 1.0,
                   "strength of the seed's height fog band in the sky"),
      scalar_param("sky_intensity", 1.0, 0.0, 10.0,
                   "brightness of the night sky (gradient, stars, clouds)"),
  };
}

// Level with the horizon (rays along the lake that graze the crests, long cell walks), from just
// above the water, and looking up (sky, reflections of nothing).
std::vector<CameraPose> test_poses(const CameraPose& def) {
  CameraPose level = def;
  level.target = level.position + glm::dvec3(1.0, 0.0, 0.35);
  level.fov_deg = 35.0;
  CameraPose low = level;
  low.position.y = -0.7;
  low.target = low.position + glm::dvec3(-0.4, -0.01, 1.0);
  CameraPose up = def;
  up.target = up.position + glm::dvec3(0.2, 2.0, 0.5);
  return {level, low, up};
}

}  // namespace lantern_festival

SceneInfo lantern_festival_scene_info() {
  SceneInfo info;
  info.name = "lantern_festival";
  info.description =
      "Paper lanterns floating on a night lake (seed 000): an unbounded blue-noise-jittered grid "
      "of "
      "glowing lanterns (paper, wood, metal) riding animated waves, flickering candles, a "
      "procedural moonlit sky with height fog, and the sky and lanterns reflected in the water.";
  info.params = lantern_festival::lantern_festival_params();
  // Low over the water in the corridor between two columns of lanterns (see the default timeline).
  info.default_camera = CameraPose{{4.0, 0.5, -10.0}, {2.5, 0.1, 4.0}, 50.0, 0.0};
  info.test_poses = lantern_festival::test_poses(info.default_camera);
  info.shader = "lantern_festival/lantern_festival.glsl";
  info.counts_sdf_evals = true;
  info.draws_surfaces = true;
  info.make = [] { return std::unique_ptr<Scene>(new lantern_festival::LanternFestivalScene()); };
  return info;
}

}  // namespace sdfreel
