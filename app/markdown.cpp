#include "app/markdown.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <imgui.h>
#include <md4c.h>

namespace shadowlab {

namespace {

enum Style : unsigned { kBold = 1, kItalic = 2, kCode = 4, kStrike = 8 };

struct Run {
  std::string text;  // "\n" alone: a hard line break
  unsigned style = 0;
  int link = -1;  // index into the document's links
};

using Runs = std::vector<Run>;

void append(Runs& runs, std::string_view text, unsigned style, int link) {
  if (text.empty()) return;
  if (!runs.empty() && runs.back().style == style && runs.back().link == link && runs.back().text != "\n" && text != "\n")
    runs.back().text.append(text);
  else
    runs.push_back({std::string(text), style, link});
}

std::string plain(const Runs& runs) {
  std::string out;
  for (const Run& r : runs) out += r.text == "\n" ? " / " : r.text;
  return out;
}

// "&amp;", "&#233;", "&#x2014;" -> UTF-8; unknown entities stay as written.
std::string decode_entity(std::string_view e) {
  if (e == "&amp;") return "&";
  if (e == "&lt;") return "<";
  if (e == "&gt;") return ">";
  if (e == "&quot;") return "\"";
  if (e == "&apos;") return "'";
  if (e == "&nbsp;") return "\xC2\xA0";
  if (e.size() > 3 && e[1] == '#') {
    const bool hex = e[2] == 'x' || e[2] == 'X';
    const std::string digits(e.substr(hex ? 3 : 2, e.size() - (hex ? 4 : 3)));
    unsigned long c = std::strtoul(digits.c_str(), nullptr, hex ? 16 : 10);
    if (c == 0 || c > 0x10FFFF) c = 0xFFFD;
    std::string out;
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
    return out;
  }
  return std::string(e);
}

}  // namespace

struct MarkdownDocument::Block {
  enum Kind { Paragraph, Heading, Code, Table, Rule };
  Kind kind = Paragraph;
  int level = 0;        // heading level 1-6
  int depth = 0;        // list nesting: content indented by this many steps
  int quote = 0;        // block-quote nesting
  std::string marker;   // the first block of a list item: "-" (a bullet) or "3."
  Runs runs;            // paragraph, heading
  std::string code;     // code block
  int columns = 0;      // table
  int header_rows = 0;
  std::vector<std::vector<Runs>> rows;
  std::vector<std::string> links;  // link targets of this block's runs
};

namespace {

using Block = MarkdownDocument::Block;

// md4c's callbacks build the list of blocks: lists and quotes become indentation of their blocks.
struct Builder {
  explicit Builder(std::vector<std::unique_ptr<Block>>& out) : blocks(out) {}
  std::vector<std::unique_ptr<Block>>& blocks;
  struct List {
    bool ordered;
    unsigned next;
  };
  std::vector<List> lists;
  int quote = 0;
  std::string pending_marker;  // a list item was entered; its first block takes the marker
  Block* current = nullptr;    // where text goes
  Runs* runs = nullptr;        // the current paragraph's, heading's or table cell's runs
  Block* table = nullptr;
  bool in_head = false;
  int bold = 0, italic = 0, code = 0, strike = 0;
  int link = -1;

  Block& start(Block::Kind kind) {
    blocks.push_back(std::make_unique<Block>());
    Block& b = *blocks.back();
    b.kind = kind;
    b.depth = static_cast<int>(lists.size());
    b.quote = quote;
    b.marker = std::move(pending_marker);
    pending_marker.clear();
    current = &b;
    runs = &b.runs;
    return b;
  }
  unsigned style() const {
    return (bold ? kBold : 0u) | (italic ? kItalic : 0u) | (code ? kCode : 0u) | (strike ? kStrike : 0u);
  }
  void text(std::string_view t) {
    if (!runs) start(Block::Paragraph);  // tight list items hold text without a paragraph
    append(*runs, t, style(), link);
  }

  int enter_block(MD_BLOCKTYPE type, void* detail) {
    switch (type) {
      case MD_BLOCK_UL: lists.push_back({false, 0}); break;
      case MD_BLOCK_OL: lists.push_back({true, static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start}); break;
      case MD_BLOCK_LI:
        if (!lists.empty()) pending_marker = lists.back().ordered ? std::to_string(lists.back().next++) + "." : "-";
        current = nullptr;
        runs = nullptr;
        break;
      case MD_BLOCK_QUOTE: ++quote; break;
      case MD_BLOCK_HR: start(Block::Rule); break;
      case MD_BLOCK_H: start(Block::Heading).level = static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level); break;
      case MD_BLOCK_CODE:
      case MD_BLOCK_HTML: start(Block::Code); break;
      case MD_BLOCK_P: start(Block::Paragraph); break;
      case MD_BLOCK_TABLE:
        table = &start(Block::Table);
        table->columns = static_cast<int>(static_cast<MD_BLOCK_TABLE_DETAIL*>(detail)->col_count);
        runs = nullptr;
        break;
      case MD_BLOCK_THEAD: in_head = true; break;
      case MD_BLOCK_TBODY: in_head = false; break;
      case MD_BLOCK_TR:
        if (table) {
          table->rows.emplace_back();
          if (in_head) ++table->header_rows;
        }
        break;
      case MD_BLOCK_TH:
      case MD_BLOCK_TD:
        if (table && !table->rows.empty()) {
          table->rows.back().emplace_back();
          runs = &table->rows.back().back();
        }
        break;
      case MD_BLOCK_DOC: break;
    }
    return 0;
  }
  int leave_block(MD_BLOCKTYPE type) {
    switch (type) {
      case MD_BLOCK_UL:
      case MD_BLOCK_OL:
        if (!lists.empty()) lists.pop_back();
        break;
      case MD_BLOCK_QUOTE: --quote; break;
      case MD_BLOCK_TABLE: table = nullptr; break;
      case MD_BLOCK_TH:
      case MD_BLOCK_TD: runs = nullptr; break;
      case MD_BLOCK_CODE:
      case MD_BLOCK_HTML:
        if (current && !current->code.empty() && current->code.back() == '\n') current->code.pop_back();
        break;
      default: break;
    }
    if (type != MD_BLOCK_TH && type != MD_BLOCK_TD && type != MD_BLOCK_TR && type != MD_BLOCK_THEAD &&
        type != MD_BLOCK_TBODY) {
      current = nullptr;
      runs = nullptr;
    }
    return 0;
  }
  int enter_span(MD_SPANTYPE type, void* detail) {
    switch (type) {
      case MD_SPAN_STRONG: ++bold; break;
      case MD_SPAN_EM: ++italic; break;
      case MD_SPAN_CODE: ++code; break;
      case MD_SPAN_DEL: ++strike; break;
      case MD_SPAN_A: {
        const MD_ATTRIBUTE& href = static_cast<MD_SPAN_A_DETAIL*>(detail)->href;
        if (!runs) start(Block::Paragraph);
        Block& owner = table ? *table : *current;
        owner.links.emplace_back(href.text, href.size);
        link = static_cast<int>(owner.links.size()) - 1;
        break;
      }
      case MD_SPAN_IMG: text("[image: "); break;
      default: break;
    }
    return 0;
  }
  int leave_span(MD_SPANTYPE type) {
    switch (type) {
      case MD_SPAN_STRONG: --bold; break;
      case MD_SPAN_EM: --italic; break;
      case MD_SPAN_CODE: --code; break;
      case MD_SPAN_DEL: --strike; break;
      case MD_SPAN_A: link = -1; break;
      case MD_SPAN_IMG: text("]"); break;
      default: break;
    }
    return 0;
  }
  int on_text(MD_TEXTTYPE type, std::string_view t) {
    if (current && current->kind == Block::Code) {
      current->code.append(t);
      return 0;
    }
    switch (type) {
      case MD_TEXT_BR: text("\n"); break;
      case MD_TEXT_SOFTBR: text(" "); break;
      case MD_TEXT_NULLCHAR: text("\xEF\xBF\xBD"); break;
      case MD_TEXT_ENTITY: text(decode_entity(t)); break;
      default: text(t); break;
    }
    return 0;
  }
};

// Inline layout: words placed left to right, wrapped at `right` (screen x); each word is an ImGui item,
// so links can be hovered and clicked.
struct InlineContext {
  const UiFonts* fonts;
  ImFont* base;  // the block's font (body, heading, table header)
  const std::vector<std::string>* links;
  std::string* clicked;
};

ImFont* font_for(const InlineContext& c, unsigned style) {
  const UiFonts* f = c.fonts;
  if (!f) return c.base;
  if (style & kCode) return f->mono ? f->mono : c.base;
  if (c.base != f->body) return c.base;  // headings are bold already
  if (style & kBold) return f->bold ? f->bold : c.base;
  if (style & kItalic) return f->italic ? f->italic : c.base;
  return c.base;
}

// The width of what the runs after `after` add to a word that ends run `after` with no space: "(" then
// `code` then ")." wrap as one word, as no space parts them.
float glued_width(const Runs& runs, std::size_t after, const InlineContext& c) {
  float width = 0.0f;
  for (std::size_t r = after + 1; r < runs.size(); ++r) {
    const std::string& t = runs[r].text;
    if (t == "\n") break;
    const std::size_t space = t.find(' ');
    ImFont* font = font_for(c, runs[r].style);
    if (font) ImGui::PushFont(font);
    width += ImGui::CalcTextSize(t.data(), t.data() + (space == std::string::npos ? t.size() : space)).x;
    if (font) ImGui::PopFont();
    if (space != std::string::npos) break;
  }
  return width;
}

// Cuts a token wider than `room` (the rest of the line) where the room ends, in whole UTF-8 characters, and
// steps `pos` back to the rest; a token that fits, or a line with no room, is left as it is.
void cut_to_room(std::string_view& token, std::size_t& pos, ImVec2& size, float room) {
  const std::string_view bare = token.substr(0, token.find_last_not_of(' ') + 1);  // without trailing spaces
  if (ImGui::CalcTextSize(bare.data(), bare.data() + bare.size()).x > room && room > 0.0f) {
    std::size_t cut = token.size();
    while (cut > 1 && ImGui::CalcTextSize(token.data(), token.data() + cut).x > room) {
      --cut;
      while (cut > 1 && (static_cast<unsigned char>(token[cut]) & 0xC0) == 0x80) --cut;  // whole UTF-8 characters
    }
    if (cut < token.size()) {
      pos -= token.size() - cut;
      token = token.substr(0, cut);
      size = ImGui::CalcTextSize(token.data(), token.data() + token.size());
    }
  }
}

// What is drawn over a token just drawn at `at`: a strike-through, a link's underline, tooltip and click.
void decorate_token(const Run& run, ImVec2 at, ImVec2 size, const InlineContext& c, bool is_link) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (run.style & kStrike) {
    const float y = at.y + size.y * 0.55f;
    draw->AddLine(ImVec2(at.x, y), ImVec2(at.x + size.x, y), ImGui::GetColorU32(ImGuiCol_Text));
  }
  if (is_link) {
    const std::string& target = (*c.links)[static_cast<std::size_t>(run.link)];
    draw->AddLine(ImVec2(at.x, at.y + size.y - 1.0f), ImVec2(at.x + size.x, at.y + size.y - 1.0f), markdown_colors::kLink);
    if (ImGui::IsItemHovered()) {
      ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
      ImGui::SetTooltip("%s\n(click to copy)", target.c_str());
    }
    if (ImGui::IsItemClicked()) {
      ImGui::SetClipboardText(target.c_str());
      if (c.clicked) *c.clicked = target;
    }
  }
}

void draw_runs(const Runs& runs, const InlineContext& c) {
  const float right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
  const float line_width = ImGui::GetContentRegionAvail().x;
  bool line_start = true;
  if (c.base) ImGui::PushFont(c.base);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Run& run = runs[r];
    if (run.text == "\n") {
      if (line_start) ImGui::NewLine();
      line_start = true;
      continue;
    }
    ImFont* font = font_for(c, run.style);
    if (font) ImGui::PushFont(font);
    const bool is_link = run.link >= 0 && c.links && run.link < static_cast<int>(c.links->size());
    if (is_link) ImGui::PushStyleColor(ImGuiCol_Text, markdown_colors::kLink);
    std::size_t pos = 0;
    const std::string& t = run.text;
    while (pos < t.size()) {
      // A token: a word and the spaces after it (leading spaces of a run stay with it).
      std::size_t end = t.find(' ', pos);
      while (end != std::string::npos && end == pos) end = t.find(' ', end + 1);
      end = end == std::string::npos ? t.size() : t.find_first_not_of(' ', end);
      if (end == std::string::npos) end = t.size();
      std::string_view token(t.data() + pos, end - pos);
      pos = end;
      if (line_start && token.find_first_not_of(' ') == std::string_view::npos) continue;  // no space at a line's start
      ImVec2 size = ImGui::CalcTextSize(token.data(), token.data() + token.size());
      if (!line_start) {
        ImGui::SameLine(0.0f, 0.0f);
        // The last word of a run with no space after it wraps together with what follows it.
        float glue = pos == t.size() && token.back() != ' ' ? glued_width(runs, r, c) : 0.0f;
        if (size.x + glue > line_width) glue = 0.0f;  // longer than a line anyway: cut where it ends
        // Trailing spaces may pass the edge: only the word has to fit.
        const std::string_view word = token.substr(0, token.find_last_not_of(' ') + 1);
        const float word_width = ImGui::CalcTextSize(word.data(), word.data() + word.size()).x;
        if (ImGui::GetCursorScreenPos().x + word_width + glue > right) {
          ImGui::NewLine();
          // The spaces a run starts with (" (the defaults)" after a bold word) do not indent the new line.
          token.remove_prefix(std::min(token.find_first_not_of(' '), token.size()));
          size = ImGui::CalcTextSize(token.data(), token.data() + token.size());
        }
      }
      // A word wider than a whole line (a narrow table column) is cut where the line ends; the rest
      // starts the next line.
      cut_to_room(token, pos, size, right - ImGui::GetCursorScreenPos().x);
      line_start = false;
      const ImVec2 at = ImGui::GetCursorScreenPos();
      ImDrawList* draw = ImGui::GetWindowDrawList();
      if (run.style & kCode) {
        // One background for the whole span: under its inner spaces too, not after its last word.
        const std::string_view word = pos < t.size() ? token : token.substr(0, token.find_last_not_of(' ') + 1);
        const float w = ImGui::CalcTextSize(word.data(), word.data() + word.size()).x;
        draw->AddRectFilled(ImVec2(at.x - 2.0f, at.y), ImVec2(at.x + w + 2.0f, at.y + size.y), markdown_colors::kCodeBackground,
                            3.0f);
      }
      ImGui::TextUnformatted(token.data(), token.data() + token.size());
      decorate_token(run, at, size, c, is_link);
    }
    if (is_link) ImGui::PopStyleColor();
    if (font) ImGui::PopFont();
  }
  if (line_start) ImGui::NewLine();  // an empty paragraph still takes its line
  if (c.base) ImGui::PopFont();
}

void draw_code(const Block& b, const UiFonts* fonts, int id) {
  if (fonts && fonts->mono) ImGui::PushFont(fonts->mono);
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec2 text = ImGui::CalcTextSize(b.code.c_str());
  const float pad = style.FramePadding.x;
  const float width = ImGui::GetContentRegionAvail().x;
  const bool scroll = text.x + 2.0f * pad > width;
  const float height = text.y + 2.0f * style.FramePadding.y + (scroll ? style.ScrollbarSize : 0.0f);
  ImGui::PushStyleColor(ImGuiCol_ChildBg, markdown_colors::kCodeBackground);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(pad, style.FramePadding.y));
  ImGui::BeginChild(("##code" + std::to_string(id)).c_str(), ImVec2(width, height), false, ImGuiWindowFlags_HorizontalScrollbar);
  ImGui::TextUnformatted(b.code.c_str());
  ImGui::EndChild();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
  if (fonts && fonts->mono) ImGui::PopFont();
}

// A cell's widths unwrapped: its whole text on one line, and its longest word (what no wrap can split).
struct CellWidths {
  float line = 0.0f, word = 0.0f;
};

CellWidths measure_cell(const Runs& runs, const InlineContext& c) {
  CellWidths w;
  float word = 0.0f;  // the word being measured, which may span runs ("(" `code` ")")
  for (const Run& run : runs) {
    if (run.text == "\n") {
      word = 0.0f;
      continue;
    }
    ImFont* font = font_for(c, run.style);
    if (font) ImGui::PushFont(font);
    const std::string& t = run.text;
    w.line += ImGui::CalcTextSize(t.data(), t.data() + t.size()).x;
    for (std::size_t pos = 0; pos <= t.size();) {
      const std::size_t space = std::min(t.find(' ', pos), t.size());
      word += ImGui::CalcTextSize(t.data() + pos, t.data() + space).x;
      w.word = std::max(w.word, word);
      if (space < t.size()) word = 0.0f;
      pos = space + 1;
    }
    if (font) ImGui::PopFont();
  }
  return w;
}

// Column widths as browsers lay out tables: every column gets its longest word, the rest of the width is
// shared in proportion to how much more each column's widest line wants; a table that fits unwrapped
// takes its lines' widths. Returned as the columns' stretch weights.
std::vector<float> column_weights(const Block& b, const InlineContext& body, const UiFonts* fonts) {
  const float padding = 2.0f * ImGui::GetStyle().CellPadding.x + 1.0f;
  std::vector<CellWidths> col(static_cast<std::size_t>(b.columns));
  for (std::size_t r = 0; r < b.rows.size(); ++r) {
    InlineContext cell = body;
    if (static_cast<int>(r) < b.header_rows && fonts && fonts->bold) cell.base = fonts->bold;
    if (cell.base) ImGui::PushFont(cell.base);
    for (std::size_t c = 0; c < col.size() && c < b.rows[r].size(); ++c) {
      const CellWidths w = measure_cell(b.rows[r][c], cell);
      col[c].line = std::max(col[c].line, w.line + padding);
      col[c].word = std::max(col[c].word, w.word + padding);
    }
    if (cell.base) ImGui::PopFont();
  }
  float lines = 0.0f, words = 0.0f;
  for (const CellWidths& w : col) {
    lines += w.line;
    words += w.word;
  }
  const float avail = ImGui::GetContentRegionAvail().x;
  std::vector<float> weights;
  for (const CellWidths& w : col) {
    float width = w.word;
    if (lines <= avail) width = w.line;
    else if (words < avail && lines > words) width = w.word + (avail - words) * (w.line - w.word) / (lines - words);
    weights.push_back(std::max(width, 1.0f));
  }
  return weights;
}

void draw_table(const Block& b, const InlineContext& body, const UiFonts* fonts, int id) {
  if (b.columns <= 0) return;
  const std::vector<float> weights = column_weights(b, body, fonts);
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  // ImGui takes the weights only when it creates a table: the table's name carries them (rounded), so a
  // panel of another width or text size gets a table laid out anew.
  std::string name = "##table" + std::to_string(id);
  for (float w : weights) name += "_" + std::to_string(static_cast<int>(w / 4.0f));
  if (!ImGui::BeginTable(name.c_str(), b.columns, flags)) return;
  for (std::size_t c = 0; c < weights.size(); ++c) ImGui::TableSetupColumn(nullptr, ImGuiTableColumnFlags_WidthStretch, weights[c]);
  for (std::size_t r = 0; r < b.rows.size(); ++r) {
    const bool header = static_cast<int>(r) < b.header_rows;
    ImGui::TableNextRow(header ? ImGuiTableRowFlags_Headers : ImGuiTableRowFlags_None);
    if (header) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(ImGuiCol_TableHeaderBg));
    for (int c = 0; c < b.columns; ++c) {
      ImGui::TableSetColumnIndex(c);
      const auto& row = b.rows[r];
      if (static_cast<std::size_t>(c) >= row.size()) continue;
      InlineContext cell = body;
      if (header && fonts && fonts->bold) cell.base = fonts->bold;
      draw_runs(row[static_cast<std::size_t>(c)], cell);
    }
  }
  ImGui::EndTable();
}

}  // namespace

MarkdownDocument::MarkdownDocument(const std::string& text) {
  const std::string markdown = without_html_comments(text);
  Builder builder(blocks_);
  MD_PARSER parser{};
  parser.abi_version = 0;
  parser.flags = MD_FLAG_TABLES | MD_FLAG_STRIKETHROUGH | MD_FLAG_PERMISSIVEAUTOLINKS | MD_FLAG_NOHTMLSPANS;
  parser.enter_block = [](MD_BLOCKTYPE t, void* d, void* u) { return static_cast<Builder*>(u)->enter_block(t, d); };
  parser.leave_block = [](MD_BLOCKTYPE t, void*, void* u) { return static_cast<Builder*>(u)->leave_block(t); };
  parser.enter_span = [](MD_SPANTYPE t, void* d, void* u) { return static_cast<Builder*>(u)->enter_span(t, d); };
  parser.leave_span = [](MD_SPANTYPE t, void*, void* u) { return static_cast<Builder*>(u)->leave_span(t); };
  parser.text = [](MD_TEXTTYPE t, const MD_CHAR* s, MD_SIZE n, void* u) {
    return static_cast<Builder*>(u)->on_text(t, std::string_view(s, n));
  };
  if (md_parse(markdown.data(), static_cast<MD_SIZE>(markdown.size()), &parser, &builder) != 0) {
    // md4c fails only when out of memory; show the text as it is rather than nothing.
    blocks_.clear();
    auto b = std::make_unique<Block>();
    b->kind = Block::Code;
    b->code = markdown;
    blocks_.push_back(std::move(b));
  }
}

MarkdownDocument::~MarkdownDocument() = default;
MarkdownDocument::MarkdownDocument(MarkdownDocument&&) noexcept = default;
MarkdownDocument& MarkdownDocument::operator=(MarkdownDocument&&) noexcept = default;

std::string MarkdownDocument::draw(const UiFonts* fonts) const {
  std::string clicked;
  const float em = ImGui::GetFontSize();
  const float step = em * 1.4f;  // one list level
  ImGui::PushID(this);
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const Block& b = *blocks_[i];
    const int id = static_cast<int>(i);
    const float indent = step * static_cast<float>(b.depth + b.quote);
    if (indent > 0.0f) ImGui::Indent(indent);
    const float top = ImGui::GetCursorScreenPos().y;
    const float left = ImGui::GetCursorScreenPos().x;
    InlineContext body{fonts, fonts ? fonts->body : nullptr, &b.links, &clicked};
    if (b.quote > 0) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    switch (b.kind) {
      case Block::Heading: {
        if (i > 0) ImGui::Dummy(ImVec2(0.0f, em * 0.5f));
        InlineContext heading = body;
        if (fonts) heading.base = b.level <= 1 ? fonts->h1 : b.level == 2 ? fonts->h2 : fonts->h3;
        draw_runs(b.runs, heading);
        if (b.level <= 2) ImGui::Separator();
        break;
      }
      case Block::Paragraph:
        if (!b.marker.empty()) {
          // The marker hangs left of the item's text, in the indentation.
          ImDrawList* draw = ImGui::GetWindowDrawList();
          const float line = ImGui::GetTextLineHeight();
          if (b.marker == "-") {
            draw->AddCircleFilled(ImVec2(left - step * 0.5f, top + line * 0.5f), em * 0.16f, ImGui::GetColorU32(ImGuiCol_Text));
          } else {
            const float w = ImGui::CalcTextSize(b.marker.c_str()).x;
            draw->AddText(ImVec2(left - w - em * 0.35f, top), ImGui::GetColorU32(ImGuiCol_Text), b.marker.c_str());
          }
        }
        draw_runs(b.runs, body);
        break;
      case Block::Code: draw_code(b, fonts, id); break;
      case Block::Table: draw_table(b, body, fonts, id); break;
      case Block::Rule: ImGui::Separator(); break;
    }
    if (b.quote > 0) {
      ImGui::PopStyleColor();
      const float bottom = ImGui::GetItemRectMax().y;
      ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(left - step * 0.6f, top), ImVec2(left - step * 0.6f + 3.0f, bottom),
                                                ImGui::GetColorU32(ImGuiCol_Separator));
    }
    // Space between blocks; items of one list sit closer together.
    const bool next_is_item = i + 1 < blocks_.size() && !blocks_[i + 1]->marker.empty() && b.depth > 0;
    if (b.kind != Block::Heading) ImGui::Dummy(ImVec2(0.0f, next_is_item ? 0.0f : em * 0.35f));
    if (indent > 0.0f) ImGui::Unindent(indent);
  }
  ImGui::PopID();
  return clicked;
}

std::vector<std::string> MarkdownDocument::outline() const {
  std::vector<std::string> out;
  for (const auto& p : blocks_) {
    const Block& b = *p;
    switch (b.kind) {
      case Block::Heading: out.push_back("h" + std::to_string(b.level) + ": " + plain(b.runs)); break;
      case Block::Paragraph:
        out.push_back((b.marker.empty() ? (b.depth > 0 ? "li" + std::to_string(b.depth) + "+" : std::string("p"))
                                        : "li" + std::to_string(b.depth) + (b.marker == "-" ? "" : " " + b.marker)) +
                      (b.quote ? " quote" : "") + ": " + plain(b.runs));
        break;
      case Block::Code: out.push_back("code: " + b.code); break;
      case Block::Rule: out.push_back("hr"); break;
      case Block::Table: {
        std::string t = "table " + std::to_string(b.columns) + "x" + std::to_string(b.rows.size()) + ":";
        for (std::size_t r = 0; r < b.rows.size(); ++r) {
          t += r ? " /" : "";
          for (std::size_t c = 0; c < b.rows[r].size(); ++c) t += (c ? " | " : " ") + plain(b.rows[r][c]);
        }
        out.push_back(t);
        break;
      }
    }
  }
  return out;
}

}  // namespace shadowlab
