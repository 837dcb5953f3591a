#pragma once
// `[video] adaptive.target_db`: the threshold (render/adaptive_sampling.h) at which a frame is
// expected to reach a PSNR, from a fit to measurements. One bench run on the lanterns (default
// timeline) at 1280x720, frames 60, 180 and 300, `final` with adaptive 1..16:
//
//   threshold  0.005  0.01   0.015  0.02   0.025  0.04   0.07
//   PSNR dB    47.24  46.47  45.97  45.51  45.07  43.63  41.54
//
// The frame's mean squared error grows about linearly with the threshold above a floor (the
// error of pixels that stop at `maximum`, and of one-sample pixels no estimate flags):
// MSE = ADAPTIVE_MSE_FLOOR + ADAPTIVE_MSE_PER_THRESHOLD * threshold fits every point within
// 0.3 dB. Other scenes and sizes land elsewhere for the same threshold (sdf_morph about 8 dB
// higher at 1280x720; the lanterns about 5 dB lower at 320x180): the target is the lanterns'.
namespace sdfreel {

constexpr double ADAPTIVE_MSE_FLOOR = 1.467e-5;  // 48.3 dB: where the threshold no longer helps
constexpr double ADAPTIVE_MSE_PER_THRESHOLD = 7.264e-4;  // MSE added per unit of threshold

// The threshold expected to give `db` (PSNR of display values in [0, 1]); 0 (every pixel takes
// `maximum`) for targets at or above the floor's PSNR.
float threshold_for_target_db(double db);

}  // namespace sdfreel
