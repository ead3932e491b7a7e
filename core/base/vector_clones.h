// TSK_VECTOR_CLONES marks a function whose loops the compiler vectorises to be built twice on
// x86-64, for the baseline and for AVX2, the one to run chosen when the library loads (function
// multiversioning through glibc's ifunc; GCC, and Clang from 14). The baseline's SSE2 cannot
// vectorise loops that mix floats, doubles and bytes. The results are the same bit for bit: the
// same IEEE operations, and neither clone may fuse multiplies and adds (AVX2 alone brings no FMA).
#pragma once

#include <cstdlib>

// Not under ThreadSanitizer, whose instrumented ifunc resolvers run before it is set up and crash
// the program as it loads.
#if defined(__x86_64__) && defined(__ELF__) && !defined(__SANITIZE_THREAD__) && \
    (defined(__clang__) ? __clang_major__ >= 14 : defined(__GNUC__))
#define TSK_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
// Code written for AVX2 by hand may be built (with TSK_AVX2 on its functions) and run where
// cpu_has_avx2() says so.
#define TSK_HAS_AVX2_CODE 1
#define TSK_AVX2 __attribute__((target("avx2")))
// Hot loops written for AVX-512 too (eight doubles a step) carry TSK_AVX512 and run where
// cpu_has_avx512() says so; setting TSK_NO_AVX512 in the environment keeps them to AVX2, for
// tests of the AVX2 loops and timings of both on one machine.
#define TSK_AVX512 __attribute__((target("avx2,avx512f,avx512vl")))
namespace tsk {
inline bool cpu_has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
inline bool cpu_has_avx512() {
  static const bool has = cpu_has_avx2() && __builtin_cpu_supports("avx512f") &&
                          __builtin_cpu_supports("avx512vl") && !std::getenv("TSK_NO_AVX512");
  return has;
}
}  // namespace tsk
#else
#define TSK_VECTOR_CLONES
#define TSK_HAS_AVX2_CODE 0
#endif
