// A lab text as Markdown text (app/markdown.h), before md4c parses it or without it: its HTML comments
// removed, its sections found.
#include "app/markdown.h"

#include <algorithm>
#include <string_view>

namespace shadowlab {

// HTML comments (`<!-- ... -->`) are invisible where Markdown is rendered; the lab texts use them to tie
// their figures to the code (tests/docs/lab_texts.py). md4c runs without inline HTML, so they go first.
// (A comment inside a code span goes too: the lab texts have none.)
std::string without_html_comments(const std::string& markdown) {
  std::string out;
  out.reserve(markdown.size());
  std::size_t at = 0;
  while (true) {
    const std::size_t open = markdown.find("<!--", at);
    const std::size_t close = open == std::string::npos ? open : markdown.find("-->", open + 4);
    if (close == std::string::npos) return out + markdown.substr(at);
    out += markdown.substr(at, open - at);
    at = close + 3;
  }
}

std::pair<std::size_t, std::size_t> markdown_section_range(const std::string& markdown, const std::vector<std::string>& headings) {
  // A heading is a line starting with '#' outside fenced code; the section runs to the next heading of
  // the same or a higher level.
  std::size_t pos = 0;
  int level = 0;
  std::size_t begin = std::string::npos;
  bool fenced = false;
  while (pos < markdown.size()) {
    std::size_t eol = markdown.find('\n', pos);
    if (eol == std::string::npos) eol = markdown.size();
    const std::string_view line(markdown.data() + pos, eol - pos);
    if (line.rfind("```", 0) == 0 || line.rfind("~~~", 0) == 0) fenced = !fenced;
    if (!fenced && !line.empty() && line[0] == '#') {
      const int l = static_cast<int>(line.find_first_not_of('#'));
      if (begin != std::string::npos && l > 0 && l <= level) return {begin, pos};
      if (begin == std::string::npos &&
          std::any_of(headings.begin(), headings.end(), [&](const std::string& h) { return line.find(h) != std::string_view::npos; })) {
        level = l;
        begin = std::min(eol + 1, markdown.size());
      }
    }
    pos = eol + 1;
  }
  if (begin == std::string::npos) return {std::string::npos, std::string::npos};
  return {begin, markdown.size()};
}

std::string markdown_section(const std::string& markdown, const std::vector<std::string>& headings) {
  const auto [begin, end] = markdown_section_range(markdown, headings);
  return begin == std::string::npos ? std::string() : markdown.substr(begin, end - begin);
}

}  // namespace shadowlab
