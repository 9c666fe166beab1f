// What the command-line tools beside the library share (cueball-stress,
// cueball-planner-benchmark): printf into a string, JSON text by hand, and
// flags checked with one line naming the flag, the value and the allowed
// range, exit status 2 (the project's rule for bad input). Header-only; not
// part of the library.
#pragma once

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include <time.h>  // clock_gettime(CLOCK_THREAD_CPUTIME_ID)

namespace cueball::tools {

/// printf into a std::string of any length (checked by the compiler like printf).
__attribute__((format(printf, 1, 2))) inline std::string fmt(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(static_cast<std::size_t>(std::max(n, 0)) + 1, '\0');
  std::vsnprintf(out.data(), out.size(), format, again);
  va_end(again);
  out.resize(static_cast<std::size_t>(std::max(n, 0)));
  return out;
}

/// A double that reads back to the same value (17 significant digits).
inline std::string num(double x) { return fmt("%.17g", x); }

/// A JSON string literal: quotes and backslashes escaped, control characters dropped.
inline std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    if (static_cast<unsigned char>(ch) >= 0x20) out += ch;
  }
  return out + "\"";
}

/// A tool's flags: a bad one is one line on stderr and exit status 2.
struct Flags {
  const char* program;

  [[noreturn]] void bad(const std::string& flag, const std::string& value, const std::string& allowed) const {
    std::fprintf(stderr, "%s: error: %s = '%s' is not allowed; allowed: %s\n", program, flag.c_str(), value.c_str(),
                 allowed.c_str());
    std::exit(2);
  }

  /// A whole number in [lo, hi] (digits only, at most 18).
  long long integer(const std::string& flag, const std::string& value, long long lo, long long hi) const {
    const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (value.empty() || value.find_first_not_of("0123456789") != std::string::npos || value.size() > 18)
      bad(flag, value, range);
    const long long x = std::stoll(value);
    if (x < lo || x > hi) bad(flag, value, range);
    return x;
  }

  /// A number in [lo, hi], the whole value read; `allowed` says so in words.
  double number(const std::string& flag, const std::string& value, double lo, double hi,
                const std::string& allowed) const {
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(value, &used);
    } catch (const std::exception&) {
      bad(flag, value, allowed);
    }
    if (used != value.size() || !(x >= lo && x <= hi)) bad(flag, value, allowed);
    return x;
  }
};

/// CPU time of the calling thread, s: a decision's cost on one core, whatever
/// else the machine runs.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Writes `text` to `path` (a --json file); a path that cannot be written is
/// the flag's bad value (exit 2).
inline void write_file(const Flags& flags, const char* flag, const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) flags.bad(flag, path, "a writable file path");
  out << text;
}

/// A tool's main: run(options), an engine error one line on stderr and exit status 1.
template <class Options, class Run>
int tool_main(const char* program, const Options& options, const Run& run) {
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 1;
  }
}

}  // namespace cueball::tools
