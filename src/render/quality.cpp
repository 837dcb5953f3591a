#include "render/quality.h"

#include <cstdint>

#include "render/adaptive_sampling.h"

namespace sdfreel {

// The one place where preset numbers live. hit_eps and normal_eps are in units of the pixel
// footprint at unit distance: the renderer multiplies them by t * pixel_angle, so precision follows
// what a pixel can show instead of a fixed world-space epsilon.
float footprint_angle(float tan_half_fov, int height) {
  const float angle = 2.0f * tan_half_fov / float(height);
  return angle < MAX_FOOTPRINT_ANGLE ? angle : MAX_FOOTPRINT_ANGLE;
}

MarchSettings march_settings(Quality q) {
  switch (q) {
    case Quality::Draft:
      return MarchSettings{96, 0.05f, 1.2f, 0.25f, 24, 48, 120.0f};
    case Quality::Final:
      return MarchSettings{256, 0.05f, 1.2f, 0.25f, 64, 128, 200.0f};
    case Quality::Reference:
      return MarchSettings{1024, 0.05f, 1.0f, 0.25f, 256, 512, 200.0f};
  }
  return march_settings(Quality::Final);
}

// The textbook loop: `if (d < 0.001) break; t += d;` for at most 256 steps, the far limit of
// `final`, and a 1e-3 world-unit normal step. Here hit_eps and normal_eps are world units.
MarchSettings naive_march_settings() {
  MarchSettings m{256, 1e-3f, 1.0f, 1e-3f, 64, 128, 120.0f};
  m.naive = true;
  return m;
}

int preset_samples(Quality q) {
  switch (q) {
    case Quality::Draft:
      return 1;
    case Quality::Final:
      return 16;
    case Quality::Reference:
      return 64;
  }
  return 4;
}

// The baseline at the sample count of `final`, so that the two differ only in how they march.
int naive_preset_samples() {
  return preset_samples(Quality::Final);
}

// `final`'s numbers are the default timeline's, measured with the bench (docs/performance.md,
// "Adaptive sampling"); draft's and reference's are not tuned.
AdaptiveSampling adaptive_preset(Quality q) {
  switch (q) {
    case Quality::Draft:
      return AdaptiveSampling{true, 1, 4, 0.01f};
    case Quality::Final:
      return AdaptiveSampling{true, 1, 16, 0.02f};
    case Quality::Reference:
      return AdaptiveSampling{true, 8, 64, 0.001f};
  }
  return adaptive_preset(Quality::Final);
}

bool small_frame(int width, int height) {
  return int64_t(width) * height < int64_t(320) * 180;
}

// The lanterns at 160x90 (docs/performance.md, "Adaptive sampling"): 42.3 dB in 0.9x the time of
// fixed 16 samples (39.9 dB). A minimum of 4, since two first samples too often miss a star or a
// distant lantern and look converged; a maximum of 28, where R2's points are spread well.
AdaptiveSampling adaptive_preset(Quality q, int width, int height) {
  if (q == Quality::Final && small_frame(width, height))
    return AdaptiveSampling{true, 4, 28, 0.008f};
  return adaptive_preset(q);
}

std::optional<Quality> parse_quality(const std::string& name) {
  if (name == "draft") return Quality::Draft;
  if (name == "final") return Quality::Final;
  if (name == "reference") return Quality::Reference;
  return std::nullopt;
}

const char* quality_name(Quality q) {
  switch (q) {
    case Quality::Draft:
      return "draft";
    case Quality::Final:
      return "final";
    case Quality::Reference:
      return "reference";
  }
  return "final";
}

}  // namespace sdfreel
