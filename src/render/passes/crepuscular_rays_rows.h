#pragma once
// The crepuscular-rays pass on the CPU in rows of eight-lane packets (src/sdf/lanes.h): the same
// bits as crepuscular_rays_pixel for every pixel, several times faster. Eight neighbouring pixels
// march together, each lane doing the scalar loop's operations in its order; a tap is read only
// while some lane is inside the box of texels that are not 0 (found once per run), and a lane
// stops once it has passed that box, since every later tap would add exactly 0.
#include "render/frame_plan.h"
#include "render/image.h"
#include "render/passes/crepuscular_rays.h"

namespace sdfreel {

// The row function of the pass over `occlusion` (ImagePass::rows); `occlusion` must outlive it.
ImagePass::RowFunction crepuscular_rays_rows(const CrepuscularRays& rays,
                                             const ImageRGBA& occlusion);

}  // namespace sdfreel
