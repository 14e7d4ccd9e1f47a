// The lab panel: what a student reads (the lab's text, the task, the files to edit, the Check result in
// words) and what an instructor switches (parameters, presets, the split view). One function draws it
// for the window and for `shadowlab render --panel`, from a plain description of what to show; it
// reports what the user asked for instead of acting, so it needs no window.
#pragma once

#include <optional>
#include <string>

#include "app/bench_plot.h"
#include "app/markdown.h"
#include "app/penumbra_view.h"
#include "app/ui_fonts.h"
#include "grading/check.h"
#include "grading/lab.h"
#include "core/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

class SettingsSession;

// The split view's right-hand side: the other implementation, the lab's defaults, or one of its presets.
enum class CompareWith { OtherImpl, Defaults, Preset };

struct CompareState {
  bool split = false;
  CompareWith with = CompareWith::OtherImpl;
  int preset = 0;          // index into Lab::presets when with == Preset
  float divider = 0.5f;    // share of the width left of the divider
  bool magnifier = false;
};

// A lab's text: its README.md as written (Markdown), parsed once, and its "Your task" section.
struct LabText {
  std::string markdown;
  MarkdownDocument document{""};
  std::string task_markdown;  // empty when the text has no such section
  MarkdownDocument task{""};
};

// The Check as it runs in the window (on a worker thread): the panel shows how long it has been running.
struct CheckProgress {
  bool running = false;
  double seconds = 0.0;   // since it started
  double expected = 0.0;  // how long this lab's last check took (0: not known yet)
};

// What the panel shows; pointers may be null where a caller has nothing (headless: no settings).
struct PanelModel {
  const Lab* lab = nullptr;
  Impl impl = Impl::Exercise;
  ParamSet* params = nullptr;
  const FrameStats* stats = nullptr;
  std::size_t triangles = 0;
  std::string scene_name;
  std::string scene_error;  // the last dropped file that could not be opened
  const LabText* lab_text = nullptr;
  const UiFonts* fonts = nullptr;  // null: the current font in every role
  float ui_scale = 1.0f;           // the panel's default width and the size control follow it
  bool resize = false;             // the scale changed: set the panel's width again
  float text_size = 1.0f;          // the user's text size (1 = 100 %), shown by the size control
  std::string gl_summary;          // "OpenGL 4.5 core, llvmpipe"
  std::vector<std::string> gl_fallbacks;  // what runs differently on this context (see context.h)
  CheckProgress check_progress;
  const CheckResult* check = nullptr;
  std::string shader_error;
  std::string cpp_status;  // a live C++ exercise's state (grading/live_cpp.h): building, live, or its error
  bool cpp_error = false;  // cpp_status is an error
  std::string status;
  CompareState* compare = nullptr;  // null: no Compare section (headless)
  SettingsSession* settings = nullptr;
  BenchPanelState* bench = nullptr;       // null: no Speed against error window
  const BenchPlots* bench_plots = nullptr;  // what it shows (null: nothing loaded)
  PenumbraPanelState* penumbra = nullptr;   // null: no Penumbra error window
  std::string penumbra_key;                 // penumbra_view_key of the view now
  bool interactive = true;  // false: headless pictures (no buttons that would do nothing)
};

// What the user asked for this frame.
struct PanelActions {
  const Lab* open_lab = nullptr;
  std::optional<Impl> impl;
  bool check = false;
  bool screenshot = false;
  bool fullscreen = false;
  bool compare_changed = false;  // the split view's other side must be rebuilt
  bool load_bench = false;       // load BenchPanelState::path into the Speed against error window
  bool measure_penumbra = false;  // measure this view against the exact penumbra (PenumbraPanelState)
  std::optional<float> text_size;  // the user moved the text size control (1 = 100 %)
  std::string copied_link;         // a link in the lab text was clicked (its target is on the clipboard)
  std::optional<std::size_t> preset;  // a preset's button (index into Lab::presets): applied with its caption
  bool solution_beside = false;       // split view with the solution on the right (presets that need it)
  float panel_right = 0.0f;           // the panel's right edge, in pixels
};

PanelActions draw_lab_panel(PanelModel& model);

// The lab after or before `lab` in the course's order (wrapping), and lab number `n` if it exists.
const Lab* neighbour_lab(const Lab& lab, int step);

// The task part of a lab's text: the section headed "Your task" / "Your part" (without its heading);
// empty when the text has none.
std::string task_section(const std::string& markdown);

// The lab's README.md, parsed, or a text saying it has none yet.
LabText load_lab_text(const Lab& lab);
// The same from text (tests, other sources).
LabText make_lab_text(std::string markdown);

// Every key the window takes, in the words the panel and --help use: {"0-9", "open a lab"}, ...
const std::vector<std::pair<std::string, std::string>>& window_keys();

// Runs the lab's check in the current GL context with a renderer of its own, as `shadowlab check` does.
// `foreign_scene`: the scene is not one of the lab's built-in ones (a model the user opened or dropped):
// graded in the lab's frame and against the solution there, as `check --scene` grades (CheckRun).
CheckResult run_lab_check(const Lab& lab, Impl impl, const Scene& scene, bool foreign_scene = false);

}  // namespace shadowlab
