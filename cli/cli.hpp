// The cueball command-line interface, as a function so tests can run it
// in-process. Exit status: 0 success, 2 bad input (one line on stderr naming
// the flag, the value and the allowed range), 1 an unexpected internal error.
#pragma once

#include <iosfwd>
#include <stdexcept>

namespace cueball::cli {

/// A check a command ran found a difference (`game replay`): its message
/// printed as one line, exit status 1.
class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace cueball::cli
