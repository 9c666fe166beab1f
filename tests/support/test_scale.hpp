// Problem sizes of the long random scans: the full size in the Release suite,
// a tenth under AddressSanitizer (the asan preset). There the point is to run
// every code path with the instrumentation, which a few thousand random cases
// do as well as forty thousand; the statistics, and the rare case a long scan
// finds, are the Release suite's job (build.sh runs both).
//
// Asked at run time, not by the compiler: the asan preset links the test
// objects the Release tree compiled (tests/CMakeLists.txt,
// CUEBALL_TEST_OBJECTS_FROM), uninstrumented, against the instrumented
// library, so only the program knows whether ASan's runtime is in it. The
// runtime defines __asan_init; without it the weak reference is null.
#pragma once

extern "C" void __asan_init() __attribute__((weak));  // NOLINT(bugprone-reserved-identifier)

namespace cueball::test {

/// True in a program linked with AddressSanitizer's runtime.
inline bool sanitized() { return __asan_init != nullptr; }

/// `full` in the Release suite, `sanitized_size` under the sanitizers.
inline int scaled(int full, int sanitized_size) { return sanitized() ? sanitized_size : full; }

}  // namespace cueball::test
