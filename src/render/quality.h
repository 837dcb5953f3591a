#pragma once
// March precision presets. Every number that a preset sets lives in quality.cpp, nowhere else.
// `sdfreel bench` measures each preset's speed against its error and README.md records why the
// numbers are what they are.
#include <optional>
#include <string>

namespace sdfreel {

enum class Quality { Draft, Final, Reference };
struct AdaptiveSampling;

struct MarchSettings {
  int max_steps;      // primary-ray step cap
  float hit_eps;      // hit threshold at unit distance; scaled by t * pixel footprint
  float step_factor;  // over-relaxation factor (1 = plain sphere tracing)
  float normal_eps;   // finite-difference step for normals, at unit distance
  int shadow_steps;   // soft-shadow step cap
  int reflect_steps;  // secondary (reflection) ray step cap
  float max_dist;     // far limit of primary rays
  // The baseline everybody writes first, for the bench: plain sphere tracing (step factor 1),
  // hit_eps and normal_eps in world units (a fixed epsilon, not a pixel footprint), no bounding
  // volumes and no cell walk. Scenes honour it in both backends.
  bool naive = false;
  // Debug output for the bench's hit/miss measure: radiance is the id of the surface the primary
  // ray's march hit (0 = none; each scene numbers its marched surfaces 1, 2, ...) in all three
  // channels, instead of a colour.
  bool hit_mask = false;
  // What the primary ray's surface shows instead of a colour, for the depth and normal passes
  // (scenes/common/surface_output.h): one of the SURFACE_ modes below.
  int surface = 0;
};

constexpr int SURFACE_COLOUR = 0;    // the picture
constexpr int SURFACE_DISTANCE = 1;  // the surface's distance along the ray, in all three channels
constexpr int SURFACE_NORMAL = 2;    // its world-space unit normal
// The distance of no surface (the sky, a miss), as Blender writes it for the background.
constexpr float NO_SURFACE_DISTANCE = 1e10f;

// The pixel footprint (radians at unit distance) that hit_eps and normal_eps are measured in:
// 2 tan(fov/2) / height, the size of a pixel at the image centre, but at most
// MAX_FOOTPRINT_ANGLE. Hard cases fov_wide and resolution_1x1 guard the cap: with a 175 degree
// field of view or a 1-pixel-high image a pixel spans tens of degrees, and epsilons that large
// hit (and take normals) a sizeable fraction of the distance away from the surface, so the
// shading point, not the silhouette, goes wrong. Both backends take this one value.
constexpr float MAX_FOOTPRINT_ANGLE = 0.01f;
float footprint_angle(float tan_half_fov, int height);

MarchSettings march_settings(Quality q);
// The `naive` bench preset: plain sphere tracing with a fixed world-space epsilon.
MarchSettings naive_march_settings();
// Samples per pixel at which the bench measured a preset (docs/performance.md, "Speed against
// error"): a preset's error budget holds at this sample count or more.
int preset_samples(Quality q);
int naive_preset_samples();
// Adaptive sampling of a preset (timeline `adaptive = true`; render/adaptive_sampling.h), enabled,
// for frames of ordinary size.
AdaptiveSampling adaptive_preset(Quality q);
// Frames with fewer pixels than 320x180: a pixel covers what 16 or more cover at 1280x720, and most
// pixels hold an edge, a strut or a star.
bool small_frame(int width, int height);
// The preset for a frame of this size: `final` on a small frame starts every pixel at 4 samples
// and goes to 28 (on larger ones adaptive_preset(Quality::Final)), which is also what the bench's
// `final` runs there (fixed 16 samples at 160x90 stayed under 40 dB).
AdaptiveSampling adaptive_preset(Quality q, int width, int height);
std::optional<Quality> parse_quality(const std::string& name);
const char* quality_name(Quality q);

}  // namespace sdfreel
