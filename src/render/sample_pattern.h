#pragma once
// Fixed sub-pixel sample positions: the R2 low-discrepancy sequence (Roberts 2018), the same for
// every pixel, so a frame never depends on threads or tile order and both backends read one list.
#include <glm/glm.hpp>
#include <vector>

namespace sdfreel {

// n offsets in [0,1)^2; n == 1 gives the pixel centre.
std::vector<glm::vec2> sample_offsets(int n);

}  // namespace sdfreel
