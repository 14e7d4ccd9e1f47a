// Lab texts are Markdown (CommonMark with GitHub's tables, parsed by md4c); the panel draws them with
// ImGui: headings in larger bold type, **strong**, *emphasis*, `code` spans on a tinted background,
// indented and fenced code blocks in a monospaced box, bulleted and numbered lists (nested), pipe tables
// as ImGui tables with a header row, links (hover shows the target; a click copies it), block quotes and
// rules. Text wraps at the window's (or the table cell's) right edge.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/ui_fonts.h"

namespace shadowlab {

// The parsed document: built once per text, drawn every frame.
class MarkdownDocument {
 public:
  explicit MarkdownDocument(const std::string& markdown);
  ~MarkdownDocument();
  MarkdownDocument(MarkdownDocument&&) noexcept;
  MarkdownDocument& operator=(MarkdownDocument&&) noexcept;

  // Draws into the current ImGui window at the cursor. `fonts` may be null (or have null members): the
  // current font is used for that role. Returns the link the user clicked this frame, or "".
  std::string draw(const UiFonts* fonts) const;

  // For tests: the blocks as one line each, "h1: text", "p: text", "code: text", "li1: text",
  // "table 3x2: a | b | c / ...", "quote: ...", "hr".
  std::vector<std::string> outline() const;

  struct Block;

 private:
  std::vector<std::unique_ptr<Block>> blocks_;
};

// Colours the renderer uses, for tests that find them in ImGui's draw data.
namespace markdown_colors {
constexpr unsigned kCodeBackground = 0xFF3A332Bu;  // IM_COL32(43, 51, 58, 255): code spans and blocks
constexpr unsigned kLink = 0xFFF5B466u;            // IM_COL32(102, 180, 245, 255)
}  // namespace markdown_colors

// The text without its HTML comments (`<!-- ... -->`), which the lab texts use to tie their figures to the
// code: MarkdownDocument draws the rest (md4c runs without inline HTML).
std::string without_html_comments(const std::string& markdown);

// The section headed "Your task" / "Your part" of a lab text (without its heading), as Markdown; empty
// when the text has none.
std::string markdown_section(const std::string& markdown, const std::vector<std::string>& headings);
// Where that section's body is in `markdown`: [first, second); both npos when there is none.
std::pair<std::size_t, std::size_t> markdown_section_range(const std::string& markdown, const std::vector<std::string>& headings);

}  // namespace shadowlab
