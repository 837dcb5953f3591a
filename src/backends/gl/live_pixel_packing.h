#pragma once
// Packs an adaptive round's live pixels into the first rows of the frame for the GL runner
// (gl_plan_runner.h): slot k holds the k-th live pixel (GL row order: bottom row first, left to
// right), and eight consecutive slots fill a 4x2 block, so llvmpipe's lanes shade neighbouring live
// pixels together instead of mostly-discarded blocks of the whole frame. Only positions move:
// every live pixel traces the same ray, so the bits stay those of the unpacked pass.
#include <cstdint>
#include <vector>

#include "render/shader_inputs.h"

namespace sdfreel {

struct LivePixelPacking {
  ShaderTexture pixels;  // at slot (window position): the live pixel's window x, y; -1 if none
  ShaderTexture slots;   // at pixel (window position): its slot's window x, y; -1 if stopped
  int rows = 0;          // window rows 0..rows-1 hold every slot
};

// `live` is row-major with row 0 at the top (render/live_pixels.h); the textures are in GL's row
// order, as shaders read them at gl_FragCoord.
LivePixelPacking pack_live_pixels(const std::vector<uint8_t>& live, int width, int height,
                                  const char* pixels_name, const char* slots_name);

}  // namespace sdfreel
