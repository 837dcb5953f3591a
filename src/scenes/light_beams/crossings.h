#pragma once
// light_beams: where the outlines of two shapes cross, found once per frame. Along a ray that
// meets a light and another shape, which of the two comes first can change only where both are
// entered at the same point, a point on both outlines: the directions of these crossings split
// the angles the two shapes share into parts that each keep one order (visibility.cpp). Shapes
// whose outlines do not cross (apart, or one inside the other) keep one order everywhere.
#include "scenes/light_beams/uniforms.h"

namespace sdfreel::light_beams {

// Index of the pair {i, j} (i != j) into BeamsUniforms::crossing_first.
inline int pairIndex(int i, int j) {
  return i < j ? i * SHAPE_COUNT + j : j * SHAPE_COUNT + i;
}

// Fills u.crossings, u.crossing_first, u.pair_mode and u.pair_line from u.shapes: for each pair
// i < j, how they lie, and the points where their outlines cross (at most MAX_PAIR_CROSSINGS, and
// MAX_CROSSINGS in all; the rest is dropped and the order test falls back to one ray per part).
// Two disjoint convex shapes are split by a line (through the middle of the gap between their
// closest points, normal to it): from p on one's side, every ray that meets both meets that one
// first, so a sign says which is in front, without a ray. Computed in double from the float
// shapes.
void findCrossings(BeamsUniforms& u);

}  // namespace sdfreel::light_beams
