// The lantern_festival scene's parameters and registry entry.
#include "scenes/lantern_festival/scene.h"

namespace sdfreel {

namespace lantern_festival {

std::vector<ParamSpec> lantern_festival_params() {
  return {
      {"wave_amplitude",
       1,
       {0.15},
       0.0,
       0.5,
       "amplitude of the lake's largest wave (m); the four others follow the seed's 0.6 ratios"},
      {"wave_speed",
       1,
       {2.5},
       0.0,
       20.0,
       "wave phase speed, radians per second of TIME (seed: 2.5)"},
      {"flicker_strength",
       1,
       {1.0},
       0.0,
       2.0,
       "candle flicker depth: 0 steady, 1 the seed's flicker"},
      {"flicker_speed", 1, {1.0}, 0.0, 10.0, "candle flicker rate, 1 = the seed's"},
      {"grid_size",
       1,
       {8.0},
       2.0,
       100.0,
       "lantern spacing (m); raised to a lantern's width where smaller, so lanterns never overlap"},
      {"lantern_jitter",
       1,
       {1.0},
       0.0,
       1.0,
       "how far lanterns stray from the regular grid, as a share of the free room in their cell"},
      {"lantern_scale", 1, {1.0}, 0.25, 3.0, "lantern size, 1 = the seed's (about 2 m tall)"},
      {"candle_intensity", 1, {1.6}, 0.0, 20.0, "candle light strength (1/d^2 falloff)"},
      {"candle_color", 3, {1.0, 0.45, 0.12}, 0.0, 1.0, "candle light colour (linear Rec.709)"},
      {"paper_color", 3, {1.0, 0.78, 0.55}, 0.0, 1.0, "paper albedo (linear Rec.709)"},
      {"moon_intensity", 1, {0.25}, 0.0, 5.0, "moonlight strength (directional light and disc)"},
      {"moon_color", 3, {0.70, 0.80, 1.0}, 0.0, 1.0, "moonlight colour (linear Rec.709)"},
      {"moon_elevation", 1, {14.0}, 0.0, 90.0, "moon height above the horizon (degrees)"},
      {"moon_azimuth", 1, {8.0}, -180.0, 180.0, "moon direction (degrees from +Z towards +X)"},
      {"water_color",
       3,
       {0.003, 0.006, 0.010},
       0.0,
       1.0,
       "water's own colour under the reflections"},
      {"water_reflection_strength",
       1,
       {0.7},
       0.0,
       1.0,
       "share of sky and lanterns the lake reflects"},
      {"fog_color",
       3,
       {0.030, 0.042, 0.075},
       0.0,
       1.0,
       "fog colour at the horizon (linear Rec.709)"},
      {"fog_density", 1, {0.006}, 0.0, 1.0, "distance fog on lanterns and water, per metre"},
      {"horizon_fog", 1, {1.0}, 0.0, 1.0, "strength of the seed's height fog band in the sky"},
      {"sky_intensity",
       1,
       {1.0},
       0.0,
       10.0,
       "brightness of the night sky (gradient, stars, clouds)"},
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
  info.make = [] { return std::unique_ptr<Scene>(new lantern_festival::LanternFestivalScene()); };
  return info;
}

}  // namespace sdfreel
