#include "app/panel_lab.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <imgui.h>

#include "app/panel.h"
#include "app/settings_panel.h"
#include "app/stats_text.h"
#include "grading/platform_process.h"
#include "labs/registry.h"
#include "renderer/shader.h"
#include "core/untrusted.h"

namespace shadowlab {

namespace {

const ImVec4 kGreen(0.45f, 0.85f, 0.45f, 1.0f), kRed(1.0f, 0.45f, 0.4f, 1.0f), kHint(0.95f, 0.8f, 0.45f, 1.0f);

// Wrapped text in the disabled colour (hints): TextDisabled does not wrap.
void hint_wrapped(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
}

// The keys, folded away (one line while folded): the panel's first screen is the lab's own.
void draw_keys() {
  if (!ImGui::TreeNode("Keys: F1-F10 presets, Page Down / Up the story, 0-9 labs...")) return;
  std::string line;
  const auto& keys = window_keys();
  for (std::size_t i = 0; i < keys.size(); ++i) line += (i ? "; " : "") + keys[i].first + " " + keys[i].second;
  hint_wrapped(line + ". Not while typing in a field.");
  ImGui::TreePop();
}

// Which OpenGL the view runs on, and what runs differently there (the course's floor is 3.3 core; macOS
// stops at 4.1, which has no compute shaders).
void draw_gl(const PanelModel& m) {
  if (m.gl_summary.empty()) return;
  if (m.gl_fallbacks.empty()) {
    hint_wrapped(m.gl_summary + ": every feature runs as designed.");
    return;
  }
  ImGui::PushStyleColor(ImGuiCol_Text, kHint);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted((m.gl_summary + ", with fallbacks:").c_str());
  for (const auto& f : m.gl_fallbacks) {
    ImGui::Bullet();  // then the text as one wrapped block beside it (BulletText does not wrap)
    ImGui::TextUnformatted(f.c_str());
  }
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
}

void draw_nav(PanelModel& m, PanelActions& a) {
  if (ImGui::ArrowButton("##previous", ImGuiDir_Left)) a.open_lab = neighbour_lab(*m.lab, -1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Previous lab (P)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemSpacing.x);
  if (ImGui::BeginCombo("##lab", ("Lab " + std::to_string(m.lab->number) + "  " + m.lab->title).c_str())) {
    for (const auto& lab : all_labs()) {
      if (ImGui::Selectable((std::to_string(lab.number) + "  " + lab.title).c_str(), &lab == m.lab)) a.open_lab = &lab;
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::ArrowButton("##next", ImGuiDir_Right)) a.open_lab = neighbour_lab(*m.lab, +1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Next lab (N)");
  if (m.interactive) {
    draw_keys();
    float percent = m.text_size * 100.0f;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
    if (ImGui::SliderFloat("Text size", &percent, 50.0f, 300.0f, "%.0f %%", ImGuiSliderFlags_AlwaysClamp)) {
      a.text_size = percent / 100.0f;
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Scales the panel's text and widgets, on top of the monitor's own scale (Ctrl+click to type a value)");
  }
  draw_gl(m);
}

void draw_task(PanelModel& m, PanelActions& a) {
  if (!ImGui::CollapsingHeader("Your task", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const bool has_task = m.lab_text && !m.lab_text->task_markdown.empty();
  ImGui::PushTextWrapPos(0.0f);
  if (m.lab->exercise_files.empty()) {
    ImGui::TextUnformatted("A read-along lab: nothing to edit. Read the text, then try the presets below.");
  } else {
    if (has_task) m.lab_text->task.draw(m.fonts);
    else ImGui::TextUnformatted("Make the Check pass by editing the file(s) below.");
    ImGui::Spacing();
    // Shaders reload when saved; C++ exercises are built into the window when saved where grading runs
    // (Linux: grading/live_cpp.h), and need a rebuild elsewhere.
    bool cpp = false;
    for (const auto& file : m.lab->exercise_files) cpp |= file.ends_with(".cpp") || file.ends_with(".h");
    const char* hint = !cpp ? "Edit (saving reloads it live):"
                       : platform::grading_unavailable().empty()
                           ? "Edit and save: the window builds your file in the background and draws with it:"
                           : "Edit, rebuild (scripts/build) and start the lab again:";
    ImGui::TextColored(kHint, "%s", hint);
    for (const auto& file : m.lab->exercise_files) {
      ImGui::BulletText("%s", file.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", (data_dir() / file).string().c_str());
    }
    int impl = m.impl == Impl::Exercise ? 0 : 1;
    bool changed = ImGui::RadioButton("run my exercise", &impl, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("run the solution", &impl, 1);
    if (changed) a.impl = impl == 0 ? Impl::Exercise : Impl::Solution;
  }
  ImGui::PopTextWrapPos();
}

// One criterion: its sentence (Criterion::headline), and on hover the metric's name, value and limit as
// graded and where the limit comes from.
void draw_criterion(const Criterion& c) {
  ImGui::PushStyleColor(ImGuiCol_Text, c.passed() ? kGreen : kRed);
  ImGui::Bullet();
  ImGui::TextUnformatted(c.headline().c_str());
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s = %.4g, limit %s %.4g\n%s", c.metric.c_str(), c.value, c.direction == Criterion::kAtMost ? "<=" : ">=",
                      c.limit, c.why.c_str());
}

// A check's result, read in five seconds: the verdict, then each failure as one sentence with its limit
// and, under it, what to change (a hint already given for an earlier failure is not repeated); the
// criteria that passed folded away under one line.
void draw_check_result(const CheckResult& r, bool interactive) {
  ImGui::TextColored(r.passed() ? kGreen : kRed, "%s (%.1f s)", r.passed() ? "PASS" : "FAIL", r.seconds);
  std::size_t failed = 0;
  for (const auto& c : r.criteria) failed += c.passed() ? 0 : 1;
  if (failed > 0) {
    ImGui::SameLine();
    ImGui::TextUnformatted((std::to_string(failed) + " of " + std::to_string(r.criteria.size()) + " criteria failed").c_str());
  }
  ImGui::PushTextWrapPos(0.0f);
  if (!r.error.empty()) ImGui::TextColored(kRed, "%s", r.error.c_str());
  for (const auto& note : r.notes) ImGui::TextDisabled("%s", note.c_str());  // e.g. an edited C++ file graded from disk
  std::vector<std::string> hints;
  for (const auto& c : r.criteria) {
    if (c.passed()) continue;
    draw_criterion(c);
    const std::string hint = c.hint();
    if (hint.empty() || std::find(hints.begin(), hints.end(), hint) != hints.end()) continue;
    hints.push_back(hint);
    ImGui::Indent();
    ImGui::PushStyleColor(ImGuiCol_Text, kHint);
    ImGui::TextUnformatted(("Fix: " + hint).c_str());
    ImGui::PopStyleColor();
    ImGui::Unindent();
  }
  const std::size_t passed = r.criteria.size() - failed;
  if (passed > 0) {
    // Pictures (not interactive) show them unfolded: nobody can open the node there.
    if (!interactive) ImGui::SetNextItemOpen(true);
    if (ImGui::TreeNode("passed", "%zu of %zu criteria passed", passed, r.criteria.size())) {
      for (const auto& c : r.criteria)
        if (c.passed()) draw_criterion(c);
      ImGui::TreePop();
    }
  }
  ImGui::PopTextWrapPos();
}

void draw_check(PanelModel& m, PanelActions& a) {
  if (!m.lab->check || !ImGui::CollapsingHeader("Check", ImGuiTreeNodeFlags_DefaultOpen)) return;
  char same_as[96];
  std::snprintf(same_as, sizeof same_as, "same as: shadowlab check --lab %d --impl %s", m.lab->number, impl_name(m.impl));
  if (m.interactive) {
    const bool running = m.check_progress.running;
    if (running) ImGui::BeginDisabled();
    if (ImGui::Button("Check")) a.check = true;
    if (running) ImGui::EndDisabled();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", same_as);
  } else {
    ImGui::TextDisabled("%s", same_as);
  }
  if (m.check_progress.running) {
    // The check runs on a worker thread with a GL context of its own: the view keeps drawing meanwhile.
    const CheckProgress& p = m.check_progress;
    char label[96];
    if (p.expected > 0.0) {
      std::snprintf(label, sizeof label, "checking: %.1f s (last time %.1f s)", p.seconds, p.expected);
      ImGui::ProgressBar(static_cast<float>(std::min(0.99, p.seconds / p.expected)), ImVec2(-1.0f, 0.0f), label);
    } else {
      std::snprintf(label, sizeof label, "checking: %.1f s", p.seconds);
      // No estimate yet: a bar that sweeps once a second.
      ImGui::ProgressBar(static_cast<float>(p.seconds - static_cast<double>(static_cast<long>(p.seconds))),
                         ImVec2(-1.0f, 0.0f), label);
    }
    if (!m.check) return;
    ImGui::TextDisabled("The previous result, until this one is ready:");
  }
  if (!m.check) {
    hint_wrapped("Not checked yet: press Check to grade against the ray-cast truth.");
    return;
  }
  draw_check_result(*m.check, m.interactive);
}

// The lab's own parameters (those it declares: Lab::params) and its presets, each on its key.
void draw_parameters(PanelModel& m, PanelActions& a) {
  const auto is_labs = [&](const ParamSpec& spec) {
    return std::any_of(m.lab->params.begin(), m.lab->params.end(), [&](const ParamSpec& own) { return own.key == spec.key; });
  };
  if (!ImGui::CollapsingHeader(("Lab " + std::to_string(m.lab->number) + ": parameters and presets###lab parameters").c_str(),
                               ImGuiTreeNodeFlags_DefaultOpen))
    return;
  param_widgets(*m.params, is_labs);
  if (ImGui::Button("Defaults")) m.params->reset_to_defaults();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The lab's own values");
  float x = ImGui::GetItemRectMax().x;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  bool any_needs_exercise = false;
  for (std::size_t i = 0; i < m.lab->presets.size(); ++i) {
    const Preset& preset = m.lab->presets[i];
    // F1-F10 for the first ten (the window's keys); a preset that shows its artifact only with a working
    // exercise is marked with * while the exercise runs.
    const bool needs = m.impl == Impl::Exercise && needs_working_exercise(*m.lab, preset);
    any_needs_exercise |= needs;
    const std::string label = (i < 10 ? "F" + std::to_string(i + 1) + " " : std::string()) + preset.name + (needs ? "*" : "");
    const float w = ImGui::CalcTextSize(label.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x;
    if (x + ImGui::GetStyle().ItemSpacing.x + w < right) ImGui::SameLine();  // wrap the row of buttons
    if (ImGui::Button(label.c_str())) a.preset = i;
    x = ImGui::GetItemRectMax().x;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", preset.description.c_str());
  }
  if (any_needs_exercise) {
    ImGui::PushStyleColor(ImGuiCol_Text, kHint);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted("* the artifact it provokes is the solution's: your exercise shows it once it works. The solution's picture:");
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
    if (m.interactive && m.compare) {
      if (ImGui::Button("Solution beside it")) a.solution_beside = true;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Split view: your exercise on the left, the solution with the same values on the right");
    }
  }
  if (m.settings) m.settings->draw_presets(m.lab->number, *m.params);
  // The renderer's own controls, the same in every lab: folded away.
  if (ImGui::TreeNode("renderer", "Renderer controls (%zu)", m.params->specs().size() - m.lab->params.size())) {
    param_widgets(*m.params, [&](const ParamSpec& spec) { return !is_labs(spec); });
    ImGui::TreePop();
  }
}

void draw_compare(PanelModel& m, PanelActions& a) {
  if (!m.compare || !ImGui::CollapsingHeader("Compare", ImGuiTreeNodeFlags_DefaultOpen)) return;
  CompareState& c = *m.compare;
  a.compare_changed |= ImGui::Checkbox("Split view (S)", &c.split);
  ImGui::SameLine();
  ImGui::Checkbox("Magnifier (M)", &c.magnifier);
  if (!c.split) return;
  const char* other = m.impl == Impl::Exercise ? "solution" : "exercise";
  std::string label = c.with == CompareWith::OtherImpl ? std::string("the ") + other
                      : c.with == CompareWith::Defaults ? std::string("the lab's defaults")
                      : c.preset < static_cast<int>(m.lab->presets.size()) ? "preset " + m.lab->presets[static_cast<std::size_t>(c.preset)].name
                                                                           : std::string("a preset");
  if (ImGui::BeginCombo("right side", label.c_str())) {
    if (!m.lab->exercise_files.empty() &&
        ImGui::Selectable((std::string("the ") + other + " (same values)").c_str(), c.with == CompareWith::OtherImpl)) {
      c.with = CompareWith::OtherImpl;
      a.compare_changed = true;
    }
    if (ImGui::Selectable("the lab's defaults", c.with == CompareWith::Defaults)) {
      c.with = CompareWith::Defaults;
      a.compare_changed = true;
    }
    for (std::size_t i = 0; i < m.lab->presets.size(); ++i) {
      const bool selected = c.with == CompareWith::Preset && c.preset == static_cast<int>(i);
      if (ImGui::Selectable(("preset " + m.lab->presets[i].name).c_str(), selected)) {
        c.with = CompareWith::Preset;
        c.preset = static_cast<int>(i);
        a.compare_changed = true;
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SliderFloat("divider", &c.divider, 0.05f, 0.95f, "%.2f");
  ImGui::TextDisabled("Drag the divider line in the view; left: your values and code.");
}

void draw_stats(PanelModel& m) {
  if (!m.stats || !ImGui::CollapsingHeader("GPU time per pass", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const auto& p : m.stats->shown_passes())
    ImGui::Text("%-12.*s %7.2f ms%s", static_cast<int>(p.name.size()), p.name.data(), p.gpu_ms, p.wall_clock ? " (wall)" : "");
  if (m.stats->shown_passes().empty() && !m.stats->passes.empty())
    ImGui::TextDisabled("not timed while the pass-time line is off (T)");
  if (!m.stats->passes.empty() && m.stats->passes.front().wall_clock)
    ImGui::TextDisabled("(wall): glFinish-bracketed time; a software rasteriser's real cost");
  ImGui::Text("shadow passes run: %ld of %ld frames", m.stats->shadow_passes, m.stats->frames);
  if (m.stats->flashlight_shadow_passes > 0)
    ImGui::Text("flashlight's map drawn: %ld of %ld frames", m.stats->flashlight_shadow_passes, m.stats->frames);
  ImGui::Text("since start: %ld draws, %ld casters culled,", m.stats->draws, m.stats->casters_culled);
  ImGui::Text("  %.1f M shadow texels written", static_cast<double>(m.stats->shadow_texels_written) * 1e-6);
  ImGui::Text("%zu triangles, scene: %s", m.triangles, m.scene_name.c_str());
}

}  // namespace

PanelActions draw_lab_panel(PanelModel& m) {
  PanelActions a;
  // The panel's width follows the text size; set again when the scale changes.
  const ImGuiCond cond = m.resize ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(10, 10), cond);
  ImGui::SetNextWindowSize(ImVec2(std::min(430.0f * m.ui_scale, std::max(display.x * 0.6f, 300.0f)),
                                  // Pictures (not interactive) use the whole height.
                                  m.interactive ? std::min(display.y - 20.0f, 840.0f * m.ui_scale) : display.y - 20.0f),
                           cond);
  ImGui::Begin("shadowlab");
  draw_nav(m, a);
  if (m.stats) {
    const std::string warning = precision_warning(*m.stats);
    if (!warning.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, m.stats->moments_negative_variance >= 0.5 ? kRed : ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
      ImGui::TextWrapped("%s", warning.c_str());
      ImGui::PopStyleColor();
    }
  }
  if (!m.shader_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kRed);
    ImGui::TextWrapped("Shader error (the last good program keeps running):\n%s", m.shader_error.c_str());
    ImGui::PopStyleColor();
  }
  if (!m.cpp_status.empty()) {
    if (m.cpp_error) ImGui::PushStyleColor(ImGuiCol_Text, kRed);
    ImGui::TextWrapped("%s", shortened(m.cpp_status, 2000).c_str());
    if (m.cpp_error) ImGui::PopStyleColor();
  }
  if (!m.scene_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kRed);
    ImGui::TextWrapped("%s", shortened(m.scene_error, 600).c_str());  // bounded, whatever the caller passed
    ImGui::PopStyleColor();
  }
  // The lab's own controls first, then the Check's result (visible without scrolling at 1280x720), the
  // task, the split view, and the long lab text below them.
  draw_parameters(m, a);
  draw_check(m, a);
  draw_task(m, a);
  draw_compare(m, a);
  if (m.lab_text && ImGui::CollapsingHeader("Lab text", ImGuiTreeNodeFlags_DefaultOpen)) {
    const std::string link = m.lab_text->document.draw(m.fonts);
    if (!link.empty()) a.copied_link = link;
  }
  draw_stats(m);
  if (m.bench) {
    ImGui::Checkbox("Speed against error (bench plot)", &m.bench->open);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Error against frame time for every technique and map size, from a bench.json");
  }
  if (m.penumbra) {
    ImGui::Checkbox("Penumbra error (exact soft shadow)", &m.penumbra->open);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("This view against the shadow of a light with a size (light.size): too dark, too light");
  }
  if (m.interactive) {
    if (ImGui::Button("Screenshot (F12)")) a.screenshot = true;
    ImGui::SameLine();
    if (ImGui::Button("Fullscreen (F11)")) a.fullscreen = true;
    hint_wrapped("Drop a .gltf/.glb on the window to open it. Mouse: left drag orbits, right or middle drag pans, the wheel zooms.");
  }
  if (!m.status.empty()) ImGui::TextWrapped("%s", m.status.c_str());
  a.panel_right = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  ImGui::End();
  if (m.bench) a.load_bench = draw_bench_window(m.bench_plots, *m.bench, m.interactive);
  if (m.penumbra) a.measure_penumbra = draw_penumbra_window(*m.penumbra, m.penumbra_key, m.interactive);
  return a;
}

const Lab* neighbour_lab(const Lab& lab, int step) {
  const auto& labs = all_labs();
  for (std::size_t i = 0; i < labs.size(); ++i) {
    if (&labs[i] != &lab) continue;
    const auto n = static_cast<long>(labs.size());
    return &labs[static_cast<std::size_t>(((static_cast<long>(i) + step) % n + n) % n)];
  }
  return &labs.front();
}


std::string task_section(const std::string& markdown) {
  std::string out = markdown_section(markdown, {"Your task", "Your part"});
  const auto first = out.find_first_not_of("\n ");
  if (first == std::string::npos) return "";
  out.erase(0, first);
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

LabText make_lab_text(std::string markdown) {
  LabText t;
  t.task_markdown = task_section(markdown);
  t.task = MarkdownDocument(t.task_markdown);
  // The lab text without the task's body, which the panel shows at its top.
  const auto [begin, end] = markdown_section_range(markdown, {"Your task", "Your part"});
  t.document = MarkdownDocument(t.task_markdown.empty() ? markdown
                                                        : markdown.substr(0, begin) + "*At the top of the panel, under Your task.*\n\n" +
                                                              markdown.substr(end));
  t.markdown = std::move(markdown);
  return t;
}

LabText load_lab_text(const Lab& lab) {
  std::ifstream in(lab.text_path());
  if (!in)
    return make_lab_text("# Lab " + std::to_string(lab.number) + " - " + lab.title + "\n\n" + lab.summary + "\n\n(This lab's text, `" +
                         lab.folder() + "/README.md`, is not written yet.)\n");
  std::ostringstream s;
  s << in.rdbuf();
  return make_lab_text(s.str());
}

const std::vector<std::pair<std::string, std::string>>& window_keys() {
  static const std::vector<std::pair<std::string, std::string>> keys = {
      {"0-9", "open a lab (two in a row: labs 10-99)"},
      {"N / P", "next / previous lab"},
      {"F1-F10", "the lab's presets, with a large caption over the view (demo mode)"},
      {"Page Down / Page Up", "the lab's story: its presets in teaching order, one step forward / back (a presenter's remote sends these)"},
      {"S", "split view"},
      {"M", "magnifier"},
      {"H", "hide this panel and the pass-time line (H again shows them)"},
      {"T", "pass-time line on / off (a software rasteriser times passes only while it is shown)"},
      {"F11", "fullscreen"},
      {"R", "reset the camera (the scene framed)"},
      {"F12", "screenshot into your pictures folder (its path is shown)"},
  };
  return keys;
}

CheckResult run_lab_check(const Lab& lab, Impl impl, const Scene& scene, bool foreign_scene) {
  Renderer renderer;  // its own, so the window's renderer keeps its programs and targets
  CheckRun run;
  run.impl = impl;
  run.foreign_scene = foreign_scene;
  return run_lab_check(renderer, lab, scene, run);
}

}  // namespace shadowlab
