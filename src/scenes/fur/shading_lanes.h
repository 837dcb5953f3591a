#pragma once
// The fur's mesh fragments in lanes (MeshPass::shade8): each lane has the bits of shade_shell or
// shade_case for that fragment (tests/scenes/fur/shading_lanes_test.cpp).
#include "render/frame_plan.h"
#include "scenes/fur/case_shading.h"
#include "scenes/fur/shell_shading.h"

namespace sdfreel::fur {

void shade_shell8(const ShellLook& look, const MeshFragments8& f, FragmentColours8& out);
void shade_case8(const CaseLook& look, const MeshFragments8& f, FragmentColours8& out);

}  // namespace sdfreel::fur
