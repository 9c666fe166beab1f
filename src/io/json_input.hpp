// Internal: the library's JSON reader. Strict where nlohmann's own parse()
// is lenient, and linear in the size of the text:
//   - nesting deeper than kMaxJsonDepth is rejected (recursion over a deeper
//     value, e.g. nlohmann's dump, could overflow the stack);
//   - a NUL byte anywhere is rejected (nlohmann's lexer takes '\0' for the end
//     of the input and would silently ignore what follows it);
//   - bytes after the document are rejected (strict parsing);
//   - a key given twice in one object is rejected, naming its path (nlohmann
//     keeps the last one);
//   - a number too large for a double (1e999, the only way JSON text can carry
//     a non-finite number) is rejected naming its path.
// The document is built by our own SAX handler: nlohmann's callback parser
// scans the whole parent container after every nested object (to erase
// discarded values), quadratic in the length of an array of objects.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cueball/core/errors.hpp"

namespace cueball::detail {

/// Deeper nesting is rejected: valid documents nest at most 5 levels.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// A key as a JSON path shows it: as it is when it is a plain name (letters,
/// digits, '_', at most kMaxEchoedChars), else quoted (see quote_input()).
inline std::string path_key(std::string_view key) {
  bool plain = !key.empty() && key.size() <= kMaxEchoedChars;
  for (char c : key) plain = plain && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_');
  return plain ? std::string(key) : quote_input(key);
}

class JsonBuilder {
 public:
  using json = nlohmann::json;
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  JsonBuilder(json& root, const std::string& path) : root_(root), path_(path) {}

  bool null() { return put(json(nullptr)); }
  bool boolean(bool v) { return put(json(v)); }
  bool number_integer(number_integer_t v) { return put(json(v)); }
  bool number_unsigned(number_unsigned_t v) { return put(json(v)); }
  bool number_float(number_float_t v, const string_t&) { return put(json(v)); }
  bool string(string_t& v) { return put(json(std::move(v))); }
  bool binary(binary_t& v) { return put(json::binary(std::move(v))); }

  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(string_t& k) {
    Frame& f = frames_.back();
    if (f.value->contains(k)) {
      const std::string field = current_path() + "." + path_key(k);
      throw InvalidArgument(field, field + " is given twice (a key may appear once in an object)");
    }
    f.key = std::move(k);
    return true;
  }

  [[noreturn]] bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    if (e.id == 406) {  // out_of_range: a number too large for a double
      const std::string field = next_path();
      throw InvalidArgument(field, field + " is not a finite number (" + one_line(e.what()) + ")");
    }
    throw InvalidArgument(path_, path_ + ": malformed JSON at byte " + std::to_string(position) + ": " +
                                     one_line(e.what()));
  }

 private:
  struct Frame {
    json* value;
    std::string key;  // the pending key (objects)
  };

  // Where the next value goes: the root, the end of the open array or the
  // pending key of the open object. Returns the stored value.
  json* store(json&& v) {
    if (frames_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = frames_.back();
    if (f.value->is_array()) {
      auto& a = f.value->get_ref<json::array_t&>();
      a.push_back(std::move(v));
      return &a.back();
    }
    json& slot = (*f.value)[f.key];
    slot = std::move(v);
    return &slot;
  }
  bool put(json&& v) {
    store(std::move(v));
    return true;
  }
  bool open(json&& container) {
    if (frames_.size() >= kMaxJsonDepth)
      throw InvalidArgument(path_, path_ + " nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    json* stored = store(std::move(container));
    frames_.push_back({stored, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }

  // The JSON path of the element being read in the first `frames` open
  // containers: scenario.balls[3].position. In an array that is not the
  // innermost open one, the element is the last (the open container itself);
  // in the innermost one, the next.
  std::string path_through(std::size_t frames) const {
    std::string p = path_;
    for (std::size_t i = 0; i < frames; ++i) {
      const Frame& f = frames_[i];
      if (f.value->is_array()) {
        const std::size_t n = f.value->size();
        p += "[" + std::to_string(i + 1 < frames_.size() ? n - 1 : n) + "]";
      } else {
        p += "." + path_key(f.key);
      }
    }
    return p;
  }
  std::string current_path() const { return path_through(frames_.size() - 1); }
  std::string next_path() const { return path_through(frames_.size()); }

  json& root_;
  const std::string& path_;
  std::vector<Frame> frames_;
};

/// Parses `text` (see the rules above); every failure throws InvalidArgument,
/// a bad number or a repeated key naming its path below `path`.
inline nlohmann::json parse_json(std::string_view text, const std::string& path) {
  if (const void* nul = std::memchr(text.data(), '\0', text.size()); nul != nullptr) {
    const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - text.data());
    throw InvalidArgument(path, path + ": malformed JSON at byte " + std::to_string(at + 1) +
                                    ": a NUL byte (JSON text never contains one)");
  }
  nlohmann::json root;
  JsonBuilder builder(root, path);
  nlohmann::json::sax_parse(text.begin(), text.end(), &builder, nlohmann::json::input_format_t::json, true);
  return root;
}

}  // namespace cueball::detail
