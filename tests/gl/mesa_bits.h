#pragma once
// Where llvmpipe gives the C++ scenes' bits. The GLSL twins were made bit-identical to the CPU
// backend on Mesa 22.3 (Debian 12, LLVM 15), and on Mesa 25.0 (Debian 13, LLVM 19) once every
// expression that feeds a result goes through a precise local (det_math.glsl); Mesa 26.1 (Debian
// testing, LLVM 21) gives the same bits with no further change. On a Mesa not
// listed here the bit-exact tests hold Filament's rule instead and print how many pixels differ,
// and the golden test holds a mesh pass's GL frames (fur's shells, which rasterise differently on
// 25.0) to the CPU's by the same rule on a Mesa other than the one its .gl.framemd5 was made on.
#include <string>

#include "backends/gl/gl_backend.h"

namespace sdfreel::test {

inline const char* const BIT_EXACT_MESA[] = {"22.3", "25.0", "26.1"};

inline bool llvmpipe_bit_exact(const GlBackend& gl) {
  const std::string mesa = gl.versions()["mesa"];
  for (const char* v : BIT_EXACT_MESA)
    if (mesa.rfind(std::string(v) + ".", 0) == 0 || mesa == v) return true;
  return false;
}

}  // namespace sdfreel::test
