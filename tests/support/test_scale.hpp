// Problem sizes of the long random scans: the full size in the Release suite,
// a tenth under AddressSanitizer (the asan preset, whose test code is
// compiled with -fsanitize=address: GCC defines __SANITIZE_ADDRESS__, clang
// has __has_feature(address_sanitizer)). There the point is to run every code
// path with the instrumentation, which a few thousand random cases do as well
// as forty thousand; the statistics, and the rare case a long scan finds, are
// the Release suite's job (build.sh runs both).
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define CUEBALL_TESTS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CUEBALL_TESTS_SANITIZED 1
#endif
#endif

namespace cueball::test {

#ifdef CUEBALL_TESTS_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

/// `full` in the Release suite, `sanitized` under the sanitizers.
constexpr int scaled(int full, int sanitized) { return kSanitized ? sanitized : full; }

}  // namespace cueball::test
