// Errors reported by cueball's public API.
//
// Every check at the API boundary throws one of these with a message that
// names the offending field, its value and what is allowed. Hot physics
// kernels do not validate: they trust inputs that passed validation.
#pragma once

#include <stdexcept>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace cueball {

/// A value outside its allowed range (NaN, infinity, negative mass, ...).
/// `field()` is the parameter's name in cueball's API (e.g. "mu_s").
class InvalidArgument : public std::invalid_argument {
 public:
  InvalidArgument(std::string field, double value, std::string allowed, std::string meaning = {});
  /// A message-only form, for errors that are not about one number.
  InvalidArgument(std::string field, std::string message);

  const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

/// A well-formed request that has no physical answer, e.g. a planned shot
/// violating a validity condition of paper 001's inverse problem.
/// `condition()` is the failed condition written as an inequality.
class InfeasibleShot : public std::domain_error {
 public:
  InfeasibleShot(std::string condition, const std::string& explanation);
  const std::string& condition() const noexcept { return condition_; }

 private:
  std::string condition_;
};

/// A number as error messages show it (10 significant digits).
std::string format_number(double value);

/// `value` as format_number() shows it, unless those 10 digits would read as
/// one of `bounds` that the value is not (0.50000000001 beside the bound
/// 0.5): then as many digits as read back as the value (the shortest
/// round-trip form), so that a value beyond a bound never looks equal to it.
/// InvalidArgument's range messages show their value so, beside every number
/// of their `allowed` text.
std::string format_number_beside(double value, std::initializer_list<double> bounds);

/// Longest user string an error message echoes, in characters (UTF-8 code
/// points); longer ones are cut and end in "...".
inline constexpr std::size_t kMaxEchoedChars = 60;

/// A user-supplied string (a JSON key or value, a file name, a flag's value)
/// as error messages echo it: in double quotes, with control characters,
/// quotes, backslashes and invalid UTF-8 escaped (\n, \u0000, \xff), cut
/// after kMaxEchoedChars characters with "\u2026" (an ellipsis). The result
/// is always one line.
std::string quote_input(std::string_view text, std::size_t max_chars = kMaxEchoedChars);

/// Longest file name an error message echoes (quote_input(path, kMaxEchoedPathChars)):
/// a path is what tells the user which file, so it is cut much later.
inline constexpr std::size_t kMaxEchoedPathChars = 400;

/// An error message made safe to print as one line: control characters
/// escaped as in quote_input() (without the quotes), and a message longer than
/// 1000 bytes cut in the middle (its start names the field, its end the range).
std::string one_line(std::string_view message);

/// Throws InvalidArgument unless lo <= value <= hi (and value is finite).
void require_in_range(const char* field, double value, double lo, double hi, const char* meaning = "");

/// Throws InvalidArgument unless value is finite.
void require_finite(const char* field, double value);

}  // namespace cueball
