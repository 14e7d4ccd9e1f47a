// The lab panel: what a student reads (the lab's text, the task, the files to edit, the Check result in
// words) and what an instructor switches (parameters, presets, the split view). One function draws it
// for the window and for `shadowlab render --panel`, from a plain description of what to show; it
// reports what the user asked for instead of acting, so it needs no window.
#pragma once

#include <optional>
#include <string>

#include "app/bench_plot.h"
#include "labs/check.h"
#include "labs/lab.h"
#include "renderer/params.h"
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

// What the panel shows; pointers may be null where a caller has nothing (headless: no settings).
struct PanelModel {
  const Lab* lab = nullptr;
  Impl impl = Impl::Exercise;
  ParamSet* params = nullptr;
  const FrameStats* stats = nullptr;
  std::size_t triangles = 0;
  std::string scene_name;
  std::string scene_error;  // the last dropped file that could not be opened
  const std::string* lab_text = nullptr;  // reflowed Markdown
  const CheckResult* check = nullptr;
  std::string shader_error;
  std::string status;
  CompareState* compare = nullptr;  // null: no Compare section (headless)
  SettingsSession* settings = nullptr;
  BenchPanelState* bench = nullptr;       // null: no Speed against error window
  const BenchPlots* bench_plots = nullptr;  // what it shows (null: nothing loaded)
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
};

PanelActions draw_lab_panel(PanelModel& model);

// The lab after or before `lab` in the course's order (wrapping), and lab number `n` if it exists.
const Lab* neighbour_lab(const Lab& lab, int step);

// The task part of a lab's text: the section headed "Your task" / "Your part" (without its heading);
// empty when the text has none.
std::string task_section(const std::string& markdown);

// Lab texts are Markdown hard-wrapped at 100 columns; the panel wraps by itself, so join the lines of
// each paragraph. Headings, list items, indented code and table rows keep their own lines.
std::string reflow_markdown(const std::string& text);
// The lab's README.md reflowed, or a line saying it has no text yet.
std::string load_lab_text(const Lab& lab);

// Runs the lab's check in the current GL context with a renderer of its own, as `shadowlab check` does.
CheckResult run_lab_check(const Lab& lab, Impl impl, const Scene& scene);

}  // namespace shadowlab
