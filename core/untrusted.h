// Helpers for text and JSON that come from files a user was handed: made safe to print, and measured
// before anything recursive (or large) is built from them.
//
// Printing: every message that quotes a file's content (a URI, a name, a parser's message) passes it
// through printable(), which escapes what a terminal or the panel could act on (control characters,
// ESC sequences, C1 controls, bidirectional overrides, a NUL that would cut a C string, bytes that
// are not UTF-8) and cuts it to a bounded length, saying how long it was.
//
// JSON: parse_json_bounded() parses with nlohmann's parser, which keeps its own stack (no recursion),
// and stops it as soon as the text nests deeper or holds more values than allowed; only a tree within
// the limits is ever built and handed to code that recurses (tinygltf's extras, nlohmann's copies).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace shadowlab {

// `text` made safe to print on one line and cut to about `max_bytes` bytes (a cut text ends with
// "... (N bytes)"). Backslashes are kept as they are (Windows paths), so the function is idempotent.
std::string printable(std::string_view text, std::size_t max_bytes = 160);

// printable() in single quotes: 'text'.
std::string quote(std::string_view text, std::size_t max_bytes = 160);

// A message cut for a panel or a one-line display: at most `max_bytes` bytes, cut at a UTF-8 boundary
// and marked, with the full length named. Use on text that is already printable().
std::string shortened(std::string_view message, std::size_t max_bytes);

struct JsonLimits {
  int max_depth = 64;                  // nested arrays and objects
  std::size_t max_values = 1'000'000;  // every value, key-value pairs' values and array elements alike
};

class JsonShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses `text` into a tree, refusing it as soon as it nests deeper or holds more values than
// allowed: the parser (nlohmann's, which keeps its own stack) is stopped at the first value past a
// limit, so no more than the limits allow is ever built, and what is returned is safe for code that
// recurses. Throws JsonShapeError with one printable line (no file name) when the text is not JSON or
// breaks a limit; the message names the limit.
nlohmann::json parse_json_bounded(std::string_view text, const JsonLimits& limits);

}  // namespace shadowlab
