// sdfreel is built for one instruction set (CMakeLists.txt, SDFREEL_ISA). An AVX2 build checks
// the CPU before any other code runs, so a machine without AVX2 or F16C gets a message instead of
// an illegal-instruction crash. This file is compiled without AVX (see CMakeLists.txt).
#include <cstdio>
#include <cstdlib>

#ifdef SDFREEL_ISA_AVX2
#include <cpuid.h>

// F16C: CPUID leaf 1, ECX bit 29 (clang 14's __builtin_cpu_supports does not know "f16c").
static bool cpu_has_f16c() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  return __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C) != 0;
}

__attribute__((constructor(101))) static void sdfreel_require_avx2() {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !cpu_has_f16c()) {
    std::fputs(
        "sdfreel: this build needs a CPU with AVX2 and F16C (x86-64-v3); this CPU lacks them. "
        "Rebuild with -DSDFREEL_ISA=baseline: frames have the same bits, rendering is slower.\n",
        stderr);
    std::_Exit(1);
  }
}
#endif
