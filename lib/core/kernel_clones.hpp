// SUITE_KERNEL: a loop kernel kept out of line (so that its pointer arguments are restrict) and, with GCC on
// x86-64, also compiled for AVX2, chosen at run time where the CPU has it (ifunc): the same IEEE operations in
// the same order (AVX2 without FMA contraction), so the same results bitwise, on twice as many elements per
// instruction as the baseline SSE2. -DSUITE_NO_AVX2_CLONES builds the baseline only.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(SUITE_NO_AVX2_CLONES)
#define SUITE_KERNEL __attribute__((noinline, target_clones("avx2", "default")))
#else
#define SUITE_KERNEL __attribute__((noinline))
#endif
