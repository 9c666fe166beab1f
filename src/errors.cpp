#include "cueball/errors.hpp"

#include <cmath>
#include <sstream>

namespace cueball {

std::string format_number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

namespace {

std::string range_message(const std::string& field, double value, const std::string& allowed,
                          const std::string& meaning) {
  std::string m = field + " = " + format_number(value) + " is " +
                  (std::isfinite(value) ? "outside the allowed range " : "not a finite number; allowed: ") + allowed;
  if (!meaning.empty()) m += " (" + meaning + ")";
  return m;
}

}  // namespace

InvalidArgument::InvalidArgument(std::string field, double value, std::string allowed, std::string meaning)
    : std::invalid_argument(range_message(field, value, allowed, meaning)), field_(std::move(field)) {}

InvalidArgument::InvalidArgument(std::string field, std::string message)
    : std::invalid_argument(std::move(message)), field_(std::move(field)) {}

InfeasibleShot::InfeasibleShot(std::string condition, const std::string& explanation)
    : std::domain_error("validity condition " + condition + " fails: " + explanation),
      condition_(std::move(condition)) {}

void require_in_range(const char* field, double value, double lo, double hi, const char* meaning) {
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    throw InvalidArgument(field, value, "[" + format_number(lo) + ", " + format_number(hi) + "]", meaning);
  }
}

void require_finite(const char* field, double value) {
  if (!std::isfinite(value)) throw InvalidArgument(field, value, "any finite number");
}

}  // namespace cueball
