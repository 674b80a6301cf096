#pragma once
// x86-64's baseline has 4-wide vectors; processors since 2013 have 8-wide ones (AVX2), and many
// servers since 2017 16-wide ones (AVX-512, x86-64-v4). A function marked LUZ_VECTOR_CLONES is
// compiled for all three, and the loader picks the one the processor runs (on an AVX-512 Xeon the
// 16-wide clone renders Whitted's scene 3-4% faster than the 8-wide one). x86-64-v4 has fused
// multiply-add, which this library's build forbids the compiler to use (-ffp-contract=off): every
// clone rounds as the scalar code does, so the wavefront's lanes stay the recursion's to the bit.
// GCC only (it has the attribute since 6): Clang 14, Debian bookworm's, refuses a clone used before
// its definition, and a member function cloned this way and called from another file gave wrong
// sums in a test program (and Luz would not link). Elsewhere one build for the baseline.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LUZ_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define LUZ_VECTOR_CLONES
#endif
