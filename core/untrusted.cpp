#include "core/untrusted.h"

#include <cstdint>
#include <cstdio>

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

// nlohmann's own tree builder (the one json::parse uses), fed through a gate that counts depth and
// values and stops the parse at the first value past a limit. One linear pass; nlohmann's parse
// callbacks are no substitute: on every object's end they scan the whole enclosing array for discarded
// values, which made a million-element array take minutes.
class BoundedDom {
 public:
  using json = nlohmann::json;
  BoundedDom(json& result, const JsonLimits& limits) : dom_(result, /*allow_exceptions=*/false), limits_(limits) {}

  bool null() { return value() && dom_.null(); }
  bool boolean(bool v) { return value() && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return value() && dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) { return value() && dom_.number_float(v, s); }
  bool string(json::string_t& v) { return value() && dom_.string(v); }
  bool binary(json::binary_t& v) { return value() && dom_.binary(v); }
  bool start_object(std::size_t n) { return open() && dom_.start_object(n); }
  bool start_array(std::size_t n) { return open() && dom_.start_array(n); }
  bool key(json::string_t& k) { return dom_.key(k); }
  bool end_object() {
    --depth_;
    return dom_.end_object();
  }
  bool end_array() {
    --depth_;
    return dom_.end_array();
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
    problem_ = printable(e.what(), 240);
    return false;
  }
  const std::string& problem() const { return problem_; }

 private:
  bool value() {
    if (++values_ <= limits_.max_values) return true;
    problem_ = "the JSON holds more than " + std::to_string(limits_.max_values) + " values";
    return false;
  }
  bool open() {
    if (!value()) return false;
    if (++depth_ <= limits_.max_depth) return true;
    problem_ = "the JSON nests arrays and objects deeper than " + std::to_string(limits_.max_depth) + " levels";
    return false;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  const JsonLimits& limits_;
  int depth_ = 0;
  std::size_t values_ = 0;
  std::string problem_;
};

}  // namespace

nlohmann::json parse_json_bounded(std::string_view text, const JsonLimits& limits) {
  nlohmann::json result;
  BoundedDom sax(result, limits);
  bool ok = false;
  try {
    ok = nlohmann::json::sax_parse(text.begin(), text.end(), &sax);
  } catch (const nlohmann::json::exception& e) {  // the SAX interface reports through parse_error; be sure
    throw JsonShapeError(printable(e.what(), 240));
  }
  if (!ok) throw JsonShapeError(sax.problem().empty() ? "the JSON does not parse" : sax.problem());
  return result;
}

}  // namespace shadowlab
