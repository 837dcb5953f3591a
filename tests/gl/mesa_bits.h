#pragma once
// Where llvmpipe gives the C++ scenes' bits. The GLSL twins were made bit-identical to the CPU
// backend on Mesa 22.3 (Debian 12, LLVM 15); on Mesa 25.0 (Debian 13, LLVM 19) sdf_morph's and
// water_lily's floats differ in their last bits (5 to 1690 of 2304 pixels at 64x36, a display
// mean of at most 0.005/255; the other scenes keep every bit). On a
// Mesa not listed here the bit-exact tests hold Filament's rule instead and print how many pixels
// differ, and the golden test reads <name>.gl-mesa-X.Y.framemd5 where it exists.
#include <string>

#include "backends/gl/gl_backend.h"

namespace sdfreel::test {

inline const char* const BIT_EXACT_MESA[] = {"22.3"};

inline bool llvmpipe_bit_exact(const GlBackend& gl) {
  const std::string mesa = gl.versions()["mesa"];
  for (const char* v : BIT_EXACT_MESA)
    if (mesa.rfind(std::string(v) + ".", 0) == 0 || mesa == v) return true;
  return false;
}

}  // namespace sdfreel::test
