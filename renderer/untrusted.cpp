#include "renderer/untrusted.h"

#include <cstdint>
#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowlab {

namespace {

// The code point of the UTF-8 sequence at text[i] and its length, or a length of 0 when the bytes
// there are not well-formed UTF-8 (overlong forms, surrogates and values past U+10FFFF included).
std::pair<std::uint32_t, std::size_t> decode_utf8(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  std::size_t length = 0;
  std::uint32_t cp = 0, min = 0;
  if (b0 < 0x80) return {b0, 1};
  if ((b0 & 0xE0) == 0xC0) length = 2, cp = b0 & 0x1Fu, min = 0x80;
  else if ((b0 & 0xF0) == 0xE0) length = 3, cp = b0 & 0x0Fu, min = 0x800;
  else if ((b0 & 0xF8) == 0xF0) length = 4, cp = b0 & 0x07u, min = 0x10000;
  else return {0, 0};
  if (i + length > text.size()) return {0, 0};
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return {0, 0};
    cp = cp << 6 | (byte(i + k) & 0x3Fu);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return {0, 0};
  return {cp, length};
}

// Code points a terminal or a text layout acts on rather than shows: C0 and C1 controls, DEL, line and
// paragraph separators, and the bidirectional marks and overrides that can make text read differently
// from what it is.
bool acts_on_display(std::uint32_t cp) {
  return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0x061C || cp == 0x200E || cp == 0x200F ||
         (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069);
}

std::string escape(std::uint32_t cp) {
  switch (cp) {
    case '\n': return "\\n";
    case '\r': return "\\r";
    case '\t': return "\\t";
    default: break;
  }
  char buf[12];
  std::snprintf(buf, sizeof buf, cp < 0x80 ? "\\x%02X" : "\\u%04X", static_cast<unsigned>(cp));
  return buf;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  out.reserve(std::min(text.size(), max_bytes) + 24);
  std::size_t i = 0;
  while (i < text.size()) {
    if (out.size() >= max_bytes) {
      out += "... (" + std::to_string(text.size()) + " bytes)";
      return out;
    }
    const auto [cp, length] = decode_utf8(text, i);
    if (length == 0) {  // not UTF-8: the byte's value, escaped
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[i])));
      out += buf;
      i += 1;
    } else if (acts_on_display(cp)) {
      out += escape(cp);
      i += length;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

std::string quote(std::string_view text, std::size_t max_bytes) { return "'" + printable(text, max_bytes) + "'"; }

std::string shortened(std::string_view message, std::size_t max_bytes) {
  if (message.size() <= max_bytes) return std::string(message);
  std::size_t cut = max_bytes;
  while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
  return std::string(message.substr(0, cut)) + "... (" + std::to_string(message.size()) +
         " bytes in all; the whole message is on the terminal)";
}

namespace {

// Counts depth and values as nlohmann's parser reports them; stops it (returns false) at a limit.
class ShapeSax {
 public:
  using json = nlohmann::json;
  explicit ShapeSax(const JsonLimits& limits) : limits_(limits) {}

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(json::number_integer_t) { return value(); }
  bool number_unsigned(json::number_unsigned_t) { return value(); }
  bool number_float(json::number_float_t, const json::string_t&) { return value(); }
  bool string(json::string_t&) { return value(); }
  bool binary(json::binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& k) {
    if (stack_.size() == 1) key_ = k;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
    problem_ = printable(e.what(), 240);
    return false;
  }

  const std::string& problem() const { return problem_; }
  JsonShape shape;

 private:
  bool value() {
    if (++shape.values > limits_.max_values) {
      problem_ = "the JSON holds more than " + std::to_string(limits_.max_values) + " values";
      return false;
    }
    // An element of an array member of the root object: counted for that member.
    if (stack_.size() == 2 && stack_[1] && !stack_[0]) ++shape.root_arrays[key_];
    return true;
  }
  bool open(bool array) {
    if (!value()) return false;
    stack_.push_back(array);
    if (stack_.size() == 2 && array && !stack_[0]) shape.root_arrays[key_] += 0;  // an empty array is listed too
    shape.depth = std::max(shape.depth, static_cast<int>(stack_.size()));
    if (static_cast<int>(stack_.size()) > limits_.max_depth) {
      problem_ = "the JSON nests arrays and objects deeper than " + std::to_string(limits_.max_depth) + " levels";
      return false;
    }
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  const JsonLimits& limits_;
  std::vector<bool> stack_;  // per open container: true for an array
  std::string key_;          // the root object's key being read
  std::string problem_;
};

}  // namespace

JsonShape check_json_shape(std::string_view text, const JsonLimits& limits) {
  ShapeSax sax(limits);
  bool ok = false;
  try {
    ok = nlohmann::json::sax_parse(text.begin(), text.end(), &sax);
  } catch (const std::exception& e) {  // the SAX interface reports through parse_error; be sure anyway
    throw JsonShapeError(printable(e.what(), 240));
  }
  if (!ok) throw JsonShapeError(sax.problem().empty() ? "the JSON does not parse" : sax.problem());
  return sax.shape;
}

}  // namespace shadowlab
