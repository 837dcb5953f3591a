#pragma once
// The ACES 1.0 output transform for SDR video (RRT + ODT, 100-nit dim surround), from ACES2065-1
// to CIE XYZ (D65), in sdfreel's deterministic float math: the same bits on every machine and
// every OpenColorIO version. It follows OpenColorIO's BuiltinTransform "ACES-OUTPUT -
// ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0" step by step, with the tone curves written as the
// Academy's CTL writes them (ACESlib.Tonescales.ctl, segmented_spline_c5_fwd and _c9_fwd);
// tests/io/shipped_views_test.cpp holds it to OpenColorIO's result.
#include <glm/vec3.hpp>

#include "sdf/lanes.h"

namespace sdfreel {

glm::vec3 aces_sdr_video_to_xyz(const glm::vec3& aces2065);
// Eight pixels at once (the display transform's path), each lane with the bits of the above.
V3x8 aces_sdr_video_to_xyz(const V3x8& aces2065);

// The two tone curves in log10 units, exposed for their tests.
float rrt_tone_curve_log10(float log_x);  // segmented_spline_c5_fwd
float odt_48_nits_log10(float log_x);     // segmented_spline_c9_fwd, ODT_48nits

}  // namespace sdfreel
