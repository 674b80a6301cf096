#pragma once
// x86-64's baseline has 4-wide vectors; processors since 2013 have 8-wide ones (AVX2). A function
// marked LUZ_VECTOR_CLONES is compiled for both, and the loader picks the one the processor runs.
// No fused multiply-add (AVX2 does not imply FMA): every clone rounds as the scalar code does, so
// the wavefront's lanes stay the recursion's to the bit. (GCC has the attribute since 6, Clang
// since 14; elsewhere one build for the baseline.)
#if defined(__x86_64__) && defined(__GNUC__) && (!defined(__clang__) || __clang_major__ >= 14)
#define LUZ_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define LUZ_VECTOR_CLONES
#endif
