// Counts the program's heap allocations, to check that a kernel allocates
// nothing: include in exactly one file of a test program (it replaces the
// global operator new and delete) and compare g_allocations around a call.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace cueball::test {
inline std::atomic<long> g_allocations{0};
}  // namespace cueball::test

// (Not inlined, so that GCC does not see malloc and free paired across `new`.)
[[gnu::noinline]] void* operator new(std::size_t size) {
  ++cueball::test::g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
