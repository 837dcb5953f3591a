#pragma once
// Helpers of the end-to-end tests of the CLI: the shared ones (running the binary, scratch
// folders) and the CLI's own (framemd5 lines, a small timeline).
#include <string>
#include <vector>

#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel::test {

std::vector<std::string> framemd5_data_lines(const std::string& text);  // lines not starting with #

// A small sdf_morph timeline; `extra` is appended (more tables or keys).
std::string small_timeline(int frames, const std::string& codec = "ffv1",
                           const std::string& video = "small.mkv", const std::string& extra = "");

}  // namespace sdfreel::test
