// Lab texts as Markdown: what md4c parses into (the outline) and what the panel draws, read back from
// ImGui's draw data in a bare context with the real fonts (assets/fonts): headings larger than the body,
// code in the monospaced font on its background, tables in aligned columns, fonts scaled with the UI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/markdown.h"
#include "app/ui_fonts.h"
#include "tests/imgui_fixture.h"

namespace shadowlab {
namespace {

TEST(Markdown, OutlineHasEveryBlockKind) {
  const MarkdownDocument doc(
      "# Lab 1 - Bias\n\n"
      "Some **bold**, *emphasis*, `code` and a [link](https://example.org/x).\n"
      "A soft break joins lines.\n\n"
      "    indented code\n\n"
      "## Your task\n"
      "1. first\n"
      "2. second\n"
      "   - nested\n\n"
      "   continued\n\n"
      "```glsl\nfloat x = 1.0;\n```\n\n"
      "| a | b | c |\n|---|:-:|--:|\n| 1 | 2 | 3 |\n\n"
      "> quoted\n\n"
      "---\n");
  const std::vector<std::string> expected = {
      "h1: Lab 1 - Bias",
      "p: Some bold, emphasis, code and a link. A soft break joins lines.",
      "code: indented code",
      "h2: Your task",
      "li1 1.: first",
      "li1 2.: second",
      "li2: nested",
      "li1+: continued",
      "code: float x = 1.0;",
      "table 3x2: a | b | c / 1 | 2 | 3",
      "p quote: quoted",
      "hr",
  };
  EXPECT_EQ(doc.outline(), expected);
}

TEST(Markdown, HtmlCommentsAreInvisible) {
  // The lab texts tie figures to the code with comments right after them (tests/docs/lab_texts.py).
  const MarkdownDocument doc("at least 99.5 %<!-- = labs/x/lab.cpp:kMin*100 --> of pixels\n\n"
                             "| a | b |\n|---|---|\n| limit | <= 1<!-- = f:k --> |\n\nopen <!-- never closed\n");
  const auto o = doc.outline();
  ASSERT_EQ(o.size(), 3u);
  EXPECT_EQ(o[0], "p: at least 99.5 % of pixels");
  EXPECT_EQ(o[1].find("<!--"), std::string::npos) << o[1];
  EXPECT_NE(o[1].find("<= 1"), std::string::npos) << o[1];
  EXPECT_EQ(o[2], "p: open <!-- never closed");
}

TEST(Markdown, EntitiesAndHardBreaks) {
  const MarkdownDocument doc("a &amp; b &lt; c &#8212; d  \nnext line\n");
  ASSERT_EQ(doc.outline().size(), 1u);
  EXPECT_EQ(doc.outline()[0], "p: a & b < c \xE2\x80\x94 d / next line");
}

TEST(Markdown, SectionOfAHeading) {
  const std::string text = "# Lab\nintro\n## Your task\nEdit `x`.\n\n```\n# not a heading\n```\n### detail\nmore\n## Measured\nfigures\n";
  EXPECT_EQ(markdown_section(text, {"Your task"}), "Edit `x`.\n\n```\n# not a heading\n```\n### detail\nmore\n");
  EXPECT_EQ(markdown_section(text, {"Nothing"}), "");
}

// A glyph as ImGui drew it: a textured quad (the white pixel's UV marks untextured shapes).
struct Glyph {
  ImVec2 min, max;
  float height() const { return max.y - min.y; }
};

struct Drawn {
  std::vector<std::vector<Glyph>> glyphs;  // per draw list, in drawing order
  std::vector<std::pair<ImVec2, ImVec2>> code_backgrounds;  // bounding boxes of code-coloured shapes
  bool has(ImU32 colour) const { return has_colour.end() != std::find(has_colour.begin(), has_colour.end(), colour); }
  std::vector<ImU32> has_colour;
};

class MarkdownDraw : public BareImGuiTest {
 protected:
  void SetUp() override {
    BareImGuiTest::SetUp();
    ImGui::GetIO().DisplaySize = ImVec2(1280, 1400);
    // Lines as plain shapes, not textured quads: every textured quad drawn is then a glyph.
    ImGui::GetStyle().AntiAliasedLinesUseTex = false;
  }

  UiFonts fonts(float scale) {
    std::string warning;
    UiFonts f = build_ui_fonts(*ImGui::GetIO().Fonts, std::string(SHADOWLAB_SOURCE_DIR) + "/assets/fonts", scale, &warning);
    EXPECT_EQ(warning, "");
    EXPECT_FALSE(f.builtin);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    return f;
  }

  // Draws the document in a 600-pixel-wide window (two frames, as tables size columns on the first)
  // and collects what was drawn.
  Drawn draw(const std::string& markdown, const UiFonts* f, float width = 600.0f) {
    const MarkdownDocument doc(markdown);
    for (int frame = 0; frame < 2; ++frame) {
      ImGui::NewFrame();
      ImGui::SetNextWindowPos(ImVec2(0, 0));
      ImGui::SetNextWindowSize(ImVec2(width, 1300));
      ImGui::Begin("doc", nullptr, ImGuiWindowFlags_NoDecoration);
      doc.draw(f);
      ImGui::End();
      ImGui::Render();
    }
    const ImVec2 white = ImGui::GetIO().Fonts->TexUvWhitePixel;
    Drawn out;
    const ImDrawData* data = ImGui::GetDrawData();
    for (int l = 0; l < data->CmdListsCount; ++l) {
      const ImDrawList* list = data->CmdLists[l];
      out.glyphs.emplace_back();
      // Shapes are indexed; a glyph is 4 vertices (two triangles) whose UVs are not the white pixel.
      const auto& v = list->VtxBuffer;
      for (int i = 0; i < v.Size; ++i) {
        if (std::find(out.has_colour.begin(), out.has_colour.end(), v[i].col) == out.has_colour.end()) out.has_colour.push_back(v[i].col);
      }
      for (int i = 0; i + 3 < v.Size;) {
        const bool textured = v[i].uv.x != white.x || v[i].uv.y != white.y;
        if (textured && v[i + 2].uv.x != white.x) {
          out.glyphs.back().push_back({v[i].pos, v[i + 2].pos});
          i += 4;
          continue;
        }
        // A code background: its opaque vertices, with the transparent anti-aliasing fringe between them.
        const ImU32 code = markdown_colors::kCodeBackground, fringe = code & ~IM_COL32_A_MASK;
        if (v[i].col == code) {
          ImVec2 lo = v[i].pos, hi = v[i].pos;
          int j = i;
          for (; j < v.Size && (v[j].col == code || v[j].col == fringe); ++j) {
            if (v[j].col != code) continue;
            lo = ImVec2(std::min(lo.x, v[j].pos.x), std::min(lo.y, v[j].pos.y));
            hi = ImVec2(std::max(hi.x, v[j].pos.x), std::max(hi.y, v[j].pos.y));
          }
          out.code_backgrounds.push_back({lo, hi});
          i = j;
          continue;
        }
        ++i;
      }
    }
    return out;
  }
};

TEST_F(MarkdownDraw, HeadingsAreLargerThanTheBody) {
  const UiFonts f = fonts(1.0f);
  // "H" first in each block: the first glyph of the heading and the first of the paragraph.
  const Drawn d = draw("# Heading\n\nHeading in the body\n\n## Hb\n\n### Hc\n", &f);
  ASSERT_FALSE(d.glyphs.empty());
  const auto& g = d.glyphs[0];
  ASSERT_EQ(g.size(), 7u + 16u + 2u + 2u);
  const float h1 = g[0].height(), body = g[7].height(), h2 = g[7 + 16].height(), h3 = g[7 + 16 + 2].height();
  EXPECT_NEAR(h1 / body, 1.6f, 0.15f) << h1 << " " << body;
  EXPECT_NEAR(h2 / body, 1.3f, 0.15f) << h2 << " " << body;
  EXPECT_GT(h3, body);
  EXPECT_LT(h3, h2);
}

TEST_F(MarkdownDraw, FontsScaleWithTheUi) {
  float at[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const UiFonts f = fonts(i == 0 ? 1.0f : 2.0f);
    const Drawn d = draw("# H\n\nH\n", &f);
    ASSERT_GE(d.glyphs[0].size(), 2u);
    at[i] = d.glyphs[0][1].height();
  }
  EXPECT_NEAR(at[1] / at[0], 2.0f, 0.15f) << at[0] << " " << at[1];
}

TEST_F(MarkdownDraw, CodeSpansAndBlocksAreMonospacedOnTheirBackground) {
  const UiFonts f = fonts(1.0f);
  const Drawn d = draw("Text `iiii` text\n\n```\niiii\nMMMM\n```\n", &f);
  ASSERT_GE(d.code_backgrounds.size(), 2u) << "a span's and a block's background";
  // The span's 4 glyphs (after "Text") lie on its background.
  const auto& body = d.glyphs[0];
  ASSERT_GE(body.size(), 8u);
  const auto& span_bg = d.code_backgrounds[0];
  for (int k = 4; k < 8; ++k) {
    EXPECT_GE(body[k].min.x, span_bg.first.x);
    EXPECT_LE(body[k].max.x, span_bg.second.x);
  }
  // The block is a child window: its glyphs are in a list of their own. Monospaced: "iiii" and "MMMM"
  // advance alike (in DejaVu Sans 'M' is about 3.5 times as wide as 'i').
  const std::vector<Glyph>* block = nullptr;
  for (std::size_t l = 1; l < d.glyphs.size(); ++l)
    if (d.glyphs[l].size() == 8) block = &d.glyphs[l];
  ASSERT_NE(block, nullptr) << "no draw list with the block's 8 glyphs";
  const auto advance = [](const Glyph& a, const Glyph& b) { return (b.min.x + b.max.x - a.min.x - a.max.x) / 2; };
  const float i_run = advance((*block)[0], (*block)[3]), m_run = advance((*block)[4], (*block)[7]);
  EXPECT_NEAR(i_run, m_run, 0.5f);
  EXPECT_GT(i_run, 0.0f);
  // In the body font the same pair differs: the span is monospaced, the text around it is not.
  const Drawn prop = draw("iiii MMMM\n", &f);
  EXPECT_GT(advance(prop.glyphs[0][4], prop.glyphs[0][7]), 2.0f * advance(prop.glyphs[0][0], prop.glyphs[0][3]));
}

TEST_F(MarkdownDraw, TablesAreAlignedColumns) {
  const UiFonts f = fonts(1.0f);
  const Drawn d = draw("| a | b | c |\n|---|---|---|\n| 1 | 2 | 3 |\n| x | y | z |\n", &f);
  // A table draws column by column (one draw channel each): sort the glyphs into rows, then columns.
  std::vector<Glyph> g = d.glyphs[0];
  ASSERT_EQ(g.size(), 9u);
  const auto centre_y = [](const Glyph& a) { return (a.min.y + a.max.y) / 2; };
  std::sort(g.begin(), g.end(), [&](const Glyph& a, const Glyph& b) { return centre_y(a) < centre_y(b); });
  for (std::size_t r = 0; r < 3; ++r)
    std::sort(g.begin() + static_cast<long>(3 * r), g.begin() + static_cast<long>(3 * r + 3),
              [](const Glyph& a, const Glyph& b) { return a.min.x < b.min.x; });
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      const Glyph& cell = g[static_cast<std::size_t>(3 * row + col)];
      if (col > 0) {
        EXPECT_NEAR(centre_y(cell), centre_y(g[static_cast<std::size_t>(3 * row)]), 4.0f) << "row " << row << " is one line";
        EXPECT_GT(cell.min.x, g[static_cast<std::size_t>(3 * row + col - 1)].max.x + 20.0f) << "columns apart";
      }
      if (row > 0) {
        EXPECT_NEAR(cell.min.x, g[static_cast<std::size_t>(col)].min.x, 3.0f) << "column " << col << " is aligned";
        EXPECT_GT(cell.min.y, g[static_cast<std::size_t>(3 * (row - 1) + col)].max.y) << "rows below each other";
      }
    }
  }
  EXPECT_TRUE(d.has(ImGui::GetColorU32(ImGuiCol_TableHeaderBg))) << "the header row has its background";
}

// Columns are as wide as their longest word when the table has the room: a long word in one column and
// a digit in the other draw on two lines (header and row), not cut into three.
TEST_F(MarkdownDraw, TableColumnsFitTheirLongestWord) {
  const UiFonts f = fonts(1.0f);
  const std::string word = "abcdefghijklmnopqrstuvwxyz";
  const Drawn d = draw("| x | y |\n|---|---|\n| " + word + " | 1 |\n", &f, 300.0f);
  std::vector<float> ys;
  for (const Glyph& g : d.glyphs[0]) ys.push_back((g.min.y + g.max.y) / 2);
  ASSERT_EQ(ys.size(), word.size() + 3);
  std::sort(ys.begin(), ys.end());
  int lines = 1;
  for (std::size_t k = 1; k < ys.size(); ++k) lines += ys[k] - ys[k - 1] > 6.0f;
  EXPECT_EQ(lines, 2) << "the word is cut across lines";
}

TEST_F(MarkdownDraw, LongParagraphsWrapAtTheWindowsEdge) {
  const UiFonts f = fonts(1.0f);
  std::string words;
  for (int i = 0; i < 60; ++i) words += "word ";
  const Drawn d = draw(words, &f, 300.0f);
  float right = 0.0f, top = 1e9f, bottom = 0.0f;
  for (const Glyph& g : d.glyphs[0]) {
    right = std::max(right, g.max.x);
    top = std::min(top, g.min.y);
    bottom = std::max(bottom, g.max.y);
  }
  EXPECT_LE(right, 300.0f);
  EXPECT_GT(bottom - top, 5.0f * f.body->FontSize) << "several lines";
}

// A run that starts with a space (the text after bold or code) and wraps starts its new line flush with
// the margin, not one space in.
TEST_F(MarkdownDraw, WrappedLinesStartAtTheMargin) {
  const UiFonts f = fonts(1.0f);
  std::string text;
  for (int i = 0; i < 40; ++i) text += "**b** `c` d ";
  const Drawn d = draw(text, &f, 300.0f);
  ASSERT_FALSE(d.glyphs[0].empty());
  // The first glyph of each line: a glyph to the left of the one before it starts a line.
  std::vector<float> starts = {d.glyphs[0][0].min.x};
  for (std::size_t k = 1; k < d.glyphs[0].size(); ++k)
    if (d.glyphs[0][k].min.x < d.glyphs[0][k - 1].min.x) starts.push_back(d.glyphs[0][k].min.x);
  ASSERT_GE(starts.size(), 4u) << "several lines";
  // 'b', 'c' and 'd' differ in their left bearing by about a pixel; a space is about 5.
  for (std::size_t line = 1; line < starts.size(); ++line) EXPECT_NEAR(starts[line], starts[0], 2.0f) << "line " << line;
}

// No space between "(" and a code span, or between the span and ")": the three wrap as one word.
TEST_F(MarkdownDraw, NoBreakInsideAWordMadeOfSeveralStyles) {
  const UiFonts f = fonts(1.0f);
  std::string text;
  for (int i = 0; i < 30; ++i) text += "xx (`cc`) ";
  int lines = 0;
  for (float width = 250.0f; width < 350.0f; width += 7.0f) {
    const Drawn d = draw(text, &f, width);
    // Six glyphs a group (spaces draw none): x x ( c c ).
    ASSERT_EQ(d.glyphs[0].size(), 30u * 6u) << "width " << width;
    const auto centre_y = [](const Glyph& g) { return (g.min.y + g.max.y) / 2; };
    for (std::size_t k = 0; k < 30; ++k) {
      const auto& g = d.glyphs[0];
      EXPECT_NEAR(centre_y(g[6 * k + 2]), centre_y(g[6 * k + 3]), 3.0f) << "width " << width << ": \"(\" and the code, group " << k;
      EXPECT_NEAR(centre_y(g[6 * k + 4]), centre_y(g[6 * k + 5]), 3.0f) << "width " << width << ": the code and \")\", group " << k;
    }
    lines += 1 + static_cast<int>(std::count_if(d.glyphs[0].begin() + 1, d.glyphs[0].end(),
                                                [&](const Glyph& g) { return g.min.x < (&g - 1)->min.x; }));
  }
  EXPECT_GT(lines, 15 * 5) << "the text wraps at every width";
}

TEST_F(MarkdownDraw, LinksAreColouredAndUnderlined) {
  const UiFonts f = fonts(1.0f);
  const Drawn d = draw("see [the docs](https://example.org)\n", &f);
  EXPECT_TRUE(d.has(markdown_colors::kLink));
}

TEST(UiScale, RetinaRasterisesLargerAndDrawsAtHalfScale) {
  const UiScale windows = plan_ui_scale(1.5f, 1.0f, 1.0f);
  EXPECT_FLOAT_EQ(windows.raster, 1.5f);
  EXPECT_FLOAT_EQ(windows.style, 1.5f);
  EXPECT_FLOAT_EQ(windows.font_global, 1.0f);
  const UiScale mac = plan_ui_scale(2.0f, 2.0f, 1.25f);
  EXPECT_FLOAT_EQ(mac.raster, 2.5f);
  EXPECT_FLOAT_EQ(mac.style, 1.25f);
  EXPECT_FLOAT_EQ(mac.font_global, 0.5f);
  const UiScale nonsense = plan_ui_scale(0.0f, -1.0f, 100.0f);  // unusable values count as 1
  EXPECT_FLOAT_EQ(nonsense.raster, 1.0f);
  EXPECT_FLOAT_EQ(plan_ui_scale(1.0f, 1.0f, 5.0f).raster, 3.0f);  // the text size stops at 300 %
}

}  // namespace
}  // namespace shadowlab
