// SINEW_AVX2_CLONES: GCC compiles the function twice, for AVX2 and for the
// baseline x86-64, and the loader picks one for the processor at hand
// (target_clones). Results are the same either way: the vector code keeps the
// scalar operation order and -ffp-contract=off forbids fused multiply-adds.
// Clang 14 refuses target_clones on function templates; the only Clang build
// is the fuzzing one, where the baseline code is what matters.
#pragma once

#if defined(__clang__)
#define SINEW_AVX2_CLONES
#else
#define SINEW_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#endif
