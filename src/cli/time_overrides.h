#pragma once
// A preview's time options: `--fps` and `--duration` override [video] fps and duration (so a
// preview can cover the whole timeline in fewer frames, or only its start), and `--time-range A-B`
// selects the frames whose video time lies in [A, B] seconds, as --frames would by number.
#include <string>
#include <vector>

#include "timeline/timeline.h"

namespace sdfreel {

// "N" or "N/D" frames per second, reduced; throws UsageError naming `option` otherwise.
Rational parse_fps_option(const std::string& text, const std::string& option = "--fps");

// Applies --fps ("N" or "N/D") and --duration (seconds, > 0) where given; throws UsageError
// naming the option for a bad value or more frames than a timeline may have.
void apply_time_overrides(const std::string& fps, double duration, Timeline& tl);

// The frames i with A <= i / fps <= B of "A-B"; throws UsageError for a bad range or one that
// holds no frame of the timeline.
std::vector<int> frames_in_time_range(const std::string& range, const Timeline& tl);

}  // namespace sdfreel
