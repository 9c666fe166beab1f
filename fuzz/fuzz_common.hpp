// Shared helpers of cueball's libFuzzer targets (see fuzz/README.md).
//
// The contract under test: a reader either returns a valid value or throws
// cueball::InvalidArgument with a non-empty field and message. Any other
// exception, a crash, a sanitizer report, a hang or a broken invariant is a
// bug; the helpers below turn the last two kinds into an abort() with a
// readable line on stderr, which libFuzzer records as a crash.
#pragma once

#include <cxxabi.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <memory>
#include <typeinfo>

#include "cueball/core/errors.hpp"

namespace cueball_fuzz {

/// CUEBALL_FUZZ_VERBOSE=1 prints one line per input (accepted / rejected and
/// why): handy to check what a seed or a reproducer does.
inline bool verbose() {
  static const bool on = [] {
    const char* v = std::getenv("CUEBALL_FUZZ_VERBOSE");
    return v != nullptr && *v != '\0' && *v != '0';
  }();
  return on;
}

[[noreturn]] inline void fail(const char* what, const std::string& detail) {
  std::fprintf(stderr, "\n*** cueball fuzz: %s: %s\n", what, detail.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void check(bool ok, const char* what, const std::string& detail = {}) {
  if (!ok) fail(what, detail);
}

/// The rejection the API promises: InvalidArgument naming a field.
inline void check_rejection(const cueball::InvalidArgument& e, const char* reader) {
  check(!e.field().empty(), "InvalidArgument with an empty field()", std::string(reader) + ": " + e.what());
  check(e.what()[0] != '\0', "InvalidArgument with an empty message", std::string(reader) + ": field " + e.field());
  if (verbose()) std::fprintf(stderr, "%s: rejected [%s] %s\n", reader, e.field().c_str(), e.what());
}

inline std::string type_name(const std::type_info& t) {
  int status = 0;
  const std::unique_ptr<char, decltype(&std::free)> name(abi::__cxa_demangle(t.name(), nullptr, nullptr, &status),
                                                         &std::free);
  return status == 0 && name ? std::string(name.get()) : std::string(t.name());
}

/// For a catch (const std::exception&) after the expected handlers.
[[noreturn]] inline void unexpected(const std::exception& e, const char* where) {
  fail("unexpected exception", std::string(where) + " threw " + type_name(typeid(e)) + ": " + e.what());
}

}  // namespace cueball_fuzz
