// Errors reported by cueball's public API.
//
// Every check at the API boundary throws one of these with a message that
// names the offending field, its value and what is allowed. Hot physics
// kernels do not validate: they trust inputs that passed validation.
#pragma once

#include <stdexcept>
#include <string>

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

/// Throws InvalidArgument unless lo <= value <= hi (and value is finite).
void require_in_range(const char* field, double value, double lo, double hi, const char* meaning = "");

/// Throws InvalidArgument unless value is finite.
void require_finite(const char* field, double value);

}  // namespace cueball
