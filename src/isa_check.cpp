// sdfreel is built for one instruction set (CMakeLists.txt, SDFREEL_ISA). An AVX2 build checks
// the CPU before any other code runs, so a machine without AVX2 gets a message instead of an
// illegal-instruction crash. This file is compiled without AVX (see CMakeLists.txt).
#include <cstdio>
#include <cstdlib>

#ifdef SDFREEL_ISA_AVX2
__attribute__((constructor(101))) static void sdfreel_require_avx2() {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2")) {
    std::fputs(
        "sdfreel: this build needs a CPU with AVX2 (x86-64-v3); this CPU has none. Rebuild "
        "with -DSDFREEL_ISA=baseline: frames have the same bits, rendering is slower.\n",
        stderr);
    std::_Exit(1);
  }
}
#endif
