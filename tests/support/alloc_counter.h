// Heap allocation counter for tests: interposes malloc/calloc/realloc (glibc
// exports the real allocator as __libc_*); operator new and Eigen's aligned
// allocations both go through malloc. Include it in exactly ONE file of a
// test binary: it defines the process's malloc. Other files of the same
// binary define SINEW_ALLOC_COUNTER_DECLARE_ONLY before including it.
//
// AddressSanitizer owns malloc: the counter is not installed in sanitizer
// builds (scripts/validate); tests check SINEW_COUNT_ALLOCATIONS and skip.
#pragma once

#include <atomic>
#include <cstdlib>

#if defined(__SANITIZE_ADDRESS__)
#define SINEW_COUNT_ALLOCATIONS 0
#else
#define SINEW_COUNT_ALLOCATIONS 1
#endif

namespace sinew::test {
inline std::atomic<long> g_allocations{0};
}  // namespace sinew::test

#if SINEW_COUNT_ALLOCATIONS && !defined(SINEW_ALLOC_COUNTER_DECLARE_ONLY)
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);

void* malloc(std::size_t n) {
  sinew::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t m) {
  sinew::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, m);
}
void* realloc(void* p, std::size_t n) {
  sinew::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
}
#endif
