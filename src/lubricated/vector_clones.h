// The function attribute that compiles a vectorised pair loop's entry point once per instruction
// set and picks the clone when the library is loaded: x86-64-v3 (AVX2) and v4 (AVX-512) have the
// gathers the loops need; elsewhere (another compiler or architecture) they run scalar.
#pragma once

#ifdef LUBRICATED_VECTOR_CLONES
// given on the command line (a benchmark or test that compiles for one instruction set)
#elif defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define LUBRICATED_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define LUBRICATED_VECTOR_CLONES
#endif
