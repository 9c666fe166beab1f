#include "cueball/core/errors.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <sstream>
#include <vector>

namespace cueball {

std::string format_number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

namespace {

// The shortest text that reads back as v.
std::string round_trip(double v) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool reads_as_another(double value, const std::string& shown, double bound) {
  return bound != value && format_number(bound) == shown;
}

// Every number written in `text` (the bounds of an "allowed" text such as
// "[0, 0.5 R] = [0, 0.0142875] m"), in order.
std::vector<double> numbers_in(std::string_view text) {
  std::vector<double> out;
  const std::string s(text);
  const auto digit = [&](std::size_t k) { return k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])) != 0; };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool starts = digit(i) || ((s[i] == '-' || s[i] == '.') && digit(i + 1)) ||
                        (s[i] == '-' && i + 1 < s.size() && s[i + 1] == '.' && digit(i + 2));
    const bool inside_word = i > 0 && (std::isalnum(static_cast<unsigned char>(s[i - 1])) != 0 || s[i - 1] == '_' || s[i - 1] == '.');
    if (!starts || inside_word) continue;
    char* end = nullptr;
    const double v = std::strtod(s.c_str() + i, &end);
    if (end == s.c_str() + i) continue;
    out.push_back(v);
    i = static_cast<std::size_t>(end - s.c_str()) - 1;
  }
  return out;
}

std::string format_beside(double value, const std::vector<double>& bounds) {
  const std::string shown = format_number(value);
  if (!std::isfinite(value)) return shown;
  for (double b : bounds)
    if (reads_as_another(value, shown, b)) return round_trip(value);
  return shown;
}

}  // namespace

std::string format_number_beside(double value, std::initializer_list<double> bounds) {
  return format_beside(value, std::vector<double>(bounds));
}

namespace {

// Length of the valid UTF-8 sequence starting at text[i], or 0 if there is none.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 0;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c >= 0xE0 && c <= 0xEF) n = 3;
  else if (c >= 0xF0 && c <= 0xF4) n = 4;
  else return 0;
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  return n;
}

// Appends text with control characters, DEL and invalid UTF-8 escaped; with
// `quotes`, also '"' and '\\'. Stops after max_chars code points (returns false then).
bool append_escaped(std::string& out, std::string_view text, bool quotes, std::size_t max_chars) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < text.size(); ++chars) {
    if (chars == max_chars) return false;
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::size_t n = utf8_length(text, i);
    char buf[8];
    if (n == 0) {
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
      ++i;
    } else if (n > 1) {
      out.append(text.substr(i, n));
      i += n;
    } else if (c == '\n') {
      out += "\\n", ++i;
    } else if (c == '\r') {
      out += "\\r", ++i;
    } else if (c == '\t') {
      out += "\\t", ++i;
    } else if (c < 0x20 || c == 0x7F) {
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
      ++i;
    } else if (quotes && (c == '"' || c == '\\')) {
      out += '\\';
      out += static_cast<char>(c);
      ++i;
    } else {
      out += static_cast<char>(c);
      ++i;
    }
  }
  return true;
}

std::string range_message(const std::string& field, double value, const std::string& allowed,
                          const std::string& meaning) {
  std::string m = field + " = " + format_beside(value, numbers_in(allowed)) + " is " +
                  (std::isfinite(value) ? "outside the allowed range " : "not a finite number; allowed: ") + allowed;
  if (!meaning.empty()) m += " (" + meaning + ")";
  return m;
}

}  // namespace

std::string quote_input(std::string_view text, std::size_t max_chars) {
  std::string out = "\"";
  const bool whole = append_escaped(out, text, true, max_chars);
  out += whole ? "\"" : "\u2026\" (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string one_line(std::string_view message) {
  constexpr std::size_t kMax = 1000;
  std::string out;
  if (message.size() <= kMax) {
    append_escaped(out, message, false, kMax);
    return out;
  }
  // Cut on UTF-8 boundaries: a continuation byte never starts a piece.
  std::size_t head = kMax / 2;
  while (head > 0 && (static_cast<unsigned char>(message[head]) & 0xC0) == 0x80) --head;
  std::size_t tail = message.size() - kMax / 2;
  while (tail < message.size() && (static_cast<unsigned char>(message[tail]) & 0xC0) == 0x80) ++tail;
  append_escaped(out, message.substr(0, head), false, kMax);
  out += " \u2026 ";
  append_escaped(out, message.substr(tail), false, kMax);
  return out;
}

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
