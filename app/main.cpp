// shadowlab: the window (no arguments) and the headless commands, one renderer behind both.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/bench_cmd.h"
#include "app/bench_placement.h"
#include "app/check_cmd.h"
#include "app/exit_codes.h"
#include "app/grade_cmd.h"
#include "app/labs_cmd.h"
#include "app/render_cmd.h"
#include "app/panel_lab.h"
#include "app/window.h"

namespace {

#ifndef SHADOWLAB_VERSION
#define SHADOWLAB_VERSION "unknown"
#endif
#ifndef SHADOWLAB_EMBREE_VERSION
#define SHADOWLAB_EMBREE_VERSION "?"
#endif

std::string version_text() {
  return std::string("shadowlab ") + SHADOWLAB_VERSION + "\nbuilt with Dear ImGui " + IMGUI_VERSION + ", GLFW " +
         glfwGetVersionString() + ", Embree " + SHADOWLAB_EMBREE_VERSION + "; headless OpenGL through " +
#if SHADOWLAB_HAS_EGL
         "EGL (a hidden GLFW window where EGL fails)";
#else
         "a hidden GLFW window (built without EGL: needs a display)";
#endif
}

std::string main_footer() {
  std::string keys;
  for (const auto& [key, what] : shadowlab::window_keys()) keys += "  " + key + std::string(12 - std::min<std::size_t>(11, key.size()), ' ') + what + "\n";
  return "Exit codes (every command):\n"
         "  0  ok (check: every selected lab passed)\n"
         "  1  check: some lab failed (a criterion, or your file does not build)\n"
         "  2  usage: an unknown option or bad value, a file named on the command line that is missing or\n"
         "     invalid, an output folder that cannot be written\n"
         "  3  runtime error: no OpenGL context or window, a file of the program missing, the grader broke\n"
         "\n"
         "Environment:\n"
         "  SHADOWLAB_DATA_DIR        folder holding shaders/, labs/, assets/ (default: the source tree it was built from)\n"
         "  SHADOWLAB_SETTINGS        the window's settings file (default: settings.json in the user's config folder:\n"
         "                            $XDG_CONFIG_HOME/shadowlab or ~/.config/shadowlab on Linux,\n"
         "                            ~/Library/Application Support/shadowlab on macOS, %APPDATA%\\shadowlab on Windows)\n"
         "  SHADOWLAB_SCREENSHOTS     the folder F12 saves in (default: shadowlab/ in the user's pictures folder)\n"
         "  DISPLAY, WAYLAND_DISPLAY  where the window opens (Linux); headless commands need none with EGL\n"
         "  MESA_GL_VERSION_OVERRIDE  with MESA_GLSL_VERSION_OVERRIDE, caps Mesa's OpenGL (4.1 / 410: macOS's level)\n"
         "\n"
         "Window keys:\n" + keys +
         "\n"
         "Examples:\n"
         "  shadowlab --lab 1                          open the window on lab 1\n"
         "  shadowlab --lab 1 --preset acne            ... showing acne, for this run only (nothing given on the\n"
         "                                             command line is saved unless you change it in the window)\n"
         "  shadowlab check --lab 1                    grade your lab 1 exercise\n"
         "  shadowlab render --lab 4 --out out/lab4    one frame of lab 4, headless\n"
         "  shadowlab labs --params                    every lab and parameter\n"
         "  shadowlab labs --presets --json            every preset, the artifact it provokes and its fix\n"
         "Each command has --help, with an example.";
}

// The window's options (no command).
void add_window_options(CLI::App& app, shadowlab::WindowOptions& window_options) {
  app.add_option("--lab", window_options.lab, "Lab to open in the window")->check(CLI::Range(0, 99));
  app.add_option("--scene", window_options.scene_file, "glTF file to open instead of the built-in scene");
  app.add_option("--preset", window_options.preset,
                 "The lab's preset, over its saved values, for this run (see `shadowlab labs --presets`)");
  app.add_option("--set", window_options.assignments,
                 "Parameter value over the lab's saved values (and --preset), key=value, for this run (repeatable; see "
                 "`shadowlab labs --params`)");
  app.add_option("--impl", window_options.impl, "Show the lab's exercise or its solution")
      ->check(CLI::IsMember({"exercise", "solution"}))
      ->capture_default_str();
  app.add_option("--camera", window_options.camera,
                 "Camera for this run, \"eye=x,y,z target=x,y,z fov=deg\" (each part optional; default: the kept one, "
                 "else the scene framed)");
  app.add_option("--size", window_options.size, "Window size in pixels, WxH (default 1440x860)");
  app.add_option("--frames", window_options.frames, "Close the window after this many frames (for tests)")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--screenshot", window_options.screenshot, "Save the last frame, panel included, to this PNG");
  app.add_option("--bench", window_options.bench_file,
                 "Open the Speed against error window on this bench.json (default: docs/bench.json, when opened)");
  app.add_option("--frame-report", window_options.frame_report,
                 "On closing, write what the frames cost (times, glFinish calls, blocking reads) as JSON to this file");
  app.add_option("--script", window_options.script,
                 "Scripted input for tests: key:K,frames:N,screenshot:F,resize:WxH,iconify,restore,wait:S,drop:F");

}

CLI::App* add_render_command(CLI::App& app, shadowlab::RenderOptions& render) {
  CLI::App* render_cmd = app.add_subcommand("render", "Render one frame headless: final.png, shadow_map.png, render.json");
  render_cmd->add_option("--lab", render.lab, "Lab whose features and parameters to use")->check(CLI::Range(0, 99));
  render_cmd->add_option("--scene", render.scene_file, "glTF 2.0 file (.gltf or .glb); default: the built-in scene");
  render_cmd->add_option("--preset", render.preset, "The lab's preset (see `shadowlab labs --presets`); --set applies over it");
  render_cmd->add_option("--set", render.assignments, "Parameter value, key=value (repeatable; see `shadowlab labs --params`)");
  render_cmd->add_option("--camera", render.camera,
                         "Camera, \"eye=x,y,z target=x,y,z fov=deg\" (each part optional; default: the scene framed)");
  render_cmd->add_option("--width", render.width, "Image width in pixels")->check(CLI::Range(16, 8192));
  render_cmd->add_option("--height", render.height, "Image height in pixels")->check(CLI::Range(16, 8192));
  render_cmd->add_option("--impl", render.impl, "Run the lab's exercise or its solution")
      ->check(CLI::IsMember({"exercise", "solution"}));
  render_cmd->add_option("--out", render.out_dir, "Folder for the outputs (created if missing)")->required();
  CLI::Option* panel_flag =
      render_cmd->add_flag("--panel", render.panel, "Draw the window's panel over final.png (documentation screenshots)");
  render_cmd->add_flag("--check", render.panel_check, "With --panel: run the lab's Check first and show its result");
  render_cmd->add_flag("--penumbra", render.penumbra,
                       "With --panel: also show the Penumbra error window, this frame against the exact soft shadow of light.size")
      ->needs(panel_flag);
  render_cmd->add_option("--bench", render.bench_file, "With --panel: also show the Speed against error window on this bench.json")
      ->needs(panel_flag);
  render_cmd->add_option("--shadow-test", render.shadow_test,
                         "Shadow test in the visibility slot instead of the lab's (renderer/shadow_tests/: hard, pcf, pcss, ...); "
                         "its parameters join the lab's, for --set");
  render_cmd->add_flag("--buffers", render.buffers,
                       "Also write world positions, normals and visibility as float32 .npy files");
  render_cmd->add_option("--ui-scale", render.ui_scale, "With --panel: text and widget scale (2: as on a 200 % monitor)")
      ->check(CLI::Range(0.5, 4.0))
      ->needs(panel_flag);
  render_cmd->footer("Exit: 0 written; 2 usage (bad option, an unknown --preset, unusable --scene/--out); 3 runtime error "
                     "(no OpenGL context).\n"
                     "Example: shadowlab render --lab 1 --impl exercise --panel --check --out out/lab1\n"
                     "         shadowlab render --lab 1 --preset acne --out out/acne   (a lecture's picture)\n"
                     "Headless through EGL on Linux (no display needed); elsewhere a hidden window (needs a display).");

  return render_cmd;
}

CLI::App* add_check_command(CLI::App& app, shadowlab::CheckOptions& check) {
  CLI::App* check_cmd = app.add_subcommand("check", "Grade labs headless against the ray-cast oracle. Exit 0: all passed; 1: some failed (or your file does not build); 2: usage error; 3: grader error");
  check_cmd->add_option("--lab", check.labs, "all, one lab number, or a comma-separated list (3,4,5)");
  check_cmd->add_option("--impl", check.impl, "Grade the exercise (the file you edit; the default) or the lab's solution")
      ->check(CLI::IsMember({"exercise", "solution"}))
      ->capture_default_str();
  check_cmd->add_option("--submission", check.submission,
                        "Grade the exercise files of this folder (laid out like the project: labs/NN_slug/...) instead of yours "
                        "(Linux or WSL only)");
  check_cmd->add_option("--seed", check.seed, "Seed of the held-out conditions (light directions, map sizes, ...)")
      ->capture_default_str();
  check_cmd->add_option("--scene", check.scene_file, "glTF 2.0 file to grade on instead of the lab's scene");
  check_cmd->add_option("--json", check.json_file, "Write the results as JSON to this file");
  check_cmd->add_option("--out", check.out_dir, "Folder for renders and diff images");
  check_cmd->add_option("--preset", check.preset,
                        "Grade with this preset over the lab's defaults (every lab --lab selects must have it; see "
                        "`shadowlab labs --presets`)");
  check_cmd->add_option("--set", check.assignments, "Parameter value over the lab's defaults (and --preset), key=value (repeatable)");
  check_cmd->footer("Exit: 0 all passed; 1 some failed (or your file does not build); 2 usage; 3 grader error.\n"
                    "Example: shadowlab check --lab 1 --json out/check1.json\n"
                    "         shadowlab check --lab 1 --impl solution --preset tuned");

  return check_cmd;
}

CLI::App* add_bench_command(CLI::App& app, shadowlab::BenchOptions& bench) {
  CLI::App* bench_cmd = app.add_subcommand("bench", "Benchmark run time against error: bench.csv, bench.json, pareto.png");
  bench_cmd->add_flag("--quick", bench.quick, "Fewer map sizes, blur radii and frames (under 3 minutes here)");
  bench_cmd->add_flag("--frame-cost", bench.frame_cost_only,
                      "Only the frame-cost figures: each lab's frame against its lit pass, lab 6 against the bare two-pass baseline");
  bench_cmd->add_flag("--soft-truth", bench.soft_truth_only,
                      "Only the soft truth's cost: every scene's frame, a sun of 1 and 5 degrees, 16x16 samples at every "
                      "pixel against edge-refined sampling, and how far apart they are");
  bench_cmd->add_flag("--placement", bench.placement_only,
                      "Only the placement figures: every technique's error at offsets 1e3..1e7 and scales 1e-4..1e5 "
                      "against the origin's, and the frame cost with the local origin against without it");
  bench_cmd->add_flag("--ao", bench.ao_only,
                      "Only the AO front: SSAO (8-64 samples, blur off and on) and GTAO (slices x steps) on lab 17's "
                      "scene, GPU ms against the error to the AO truth; ao_front.json, ao_pareto.png");
  bench_cmd->add_option("--scene", bench.scene_file, "glTF 2.0 file to use as the large real model (default: PalmTree)");
  bench_cmd->add_option("--replot", bench.replot, "Only draw pareto.png again from this bench.json (no measuring)");
  bench_cmd->add_option("--out", bench.out_dir, "Folder for the outputs (created if missing)")->required();
  bench_cmd->footer("Exit: 0 written; 2 usage (unusable --scene/--out/--replot); 3 runtime error.\n"
                    "Progress goes to stderr: one line rewritten on a terminal, a line per tenth of the sweep in a log.\n"
                    "Example: shadowlab bench --quick --out out/bench");

  return bench_cmd;
}

CLI::App* add_grade_command(CLI::App& app, shadowlab::GradeOptions& grade) {
  CLI::App* grade_cmd = app.add_subcommand(
      "grade",
      "Grade a class (Linux or WSL only): each submission's labs, each in its own process with a time and a memory limit; writes "
      "results.json, results.csv, junit.xml, gradescope/<student>/results.json. Exit 0 all passed, 1 some did "
      "not, 2 usage error, 3 grader error");
  grade_cmd->add_option("submissions", grade.submissions,
                        "Folders laid out like the project (labs/NN_slug/<exercise files>), or .zip/.tar(.gz) archives of one");
  grade_cmd->add_option("--out", grade.out_dir, "Folder for the results (created if missing)")->required();
  grade_cmd->add_option("--lab", grade.labs, "all, one lab number, or a comma-separated list (3,4,5)");
  grade_cmd->add_option("--jobs", grade.jobs, "Submissions graded at once, through GNU parallel (default 1)");
  grade_cmd->add_option("--cpu-time", grade.cpu_time,
                        "CPU seconds one lab may use before it is stopped: the same verdict whatever the load (default 60)");
  grade_cmd->add_option("--timeout", grade.timeout, "Wall-clock seconds one lab may take before it is stopped (default 300)");
  grade_cmd->add_option("--memory", grade.memory_mb, "Memory one lab's process may take, MB (default 2048)");
  grade_cmd->add_option("--images", grade.images, "Diff images kept: none, failed (labs not passed; default), all")
      ->check(CLI::IsMember({"none", "failed", "all"}));
  grade_cmd->add_flag("--again", grade.again, "Grade every lab again, even those already recorded in --out");
  grade_cmd->add_flag("--merge", grade.merge_only, "Only write the reports from the results in --out (after a Slurm run)");
  grade_cmd->add_flag("--no-merge", grade.no_merge, "Only grade, do not write the reports (one task of a parallel or Slurm run)");

  return grade_cmd;
}

// `labs` and its flags.
struct LabsFlags {
  bool params = false, presets = false, json = false;
};

CLI::App* add_labs_command(CLI::App& app, LabsFlags& flags) {
  CLI::App* labs_cmd = app.add_subcommand("labs", "List the labs");
  labs_cmd->add_flag("--params", flags.params, "Also list every parameter with its range");
  labs_cmd->add_flag("--presets", flags.presets,
                     "Also list every preset (the names --preset takes) with the artifact it provokes and the preset that fixes it");
  labs_cmd->add_flag("--json", flags.json,
                     "The labs as JSON: number, slug, folder, exercise and solution files; with --presets each lab's presets "
                     "(name, description, values, provokes, fixed_by: null where none) and its story (the presets' names in "
                     "teaching order, as the window's Page Down steps through them)");
  labs_cmd->footer("Exit: 0.\nExample: shadowlab labs --params   (the keys --set takes, with their ranges)\n"
                   "         shadowlab labs --presets --json   (each preset's artifact and its fix, for scripts)");

  return labs_cmd;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"shadowlab: a teaching lab for real-time shadows in OpenGL.\n"
               "Without a command it opens the window; the commands below run headless (no display, no GPU)."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", version_text(), "Print the version and the libraries it was built with, and exit");
  app.footer(main_footer());
  app.option_defaults()->always_capture_default();  // --help shows every default (subcommands inherit this)

  shadowlab::WindowOptions window_options;
  add_window_options(app, window_options);
  shadowlab::RenderOptions render;
  CLI::App* render_cmd = add_render_command(app, render);
  shadowlab::CheckOptions check;
  CLI::App* check_cmd = add_check_command(app, check);
  shadowlab::BenchOptions bench;
  CLI::App* bench_cmd = add_bench_command(app, bench);
  shadowlab::GradeOptions grade;
  CLI::App* grade_cmd = add_grade_command(app, grade);
  LabsFlags labs;
  CLI::App* labs_cmd = add_labs_command(app, labs);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints CLI11's message and where to find --help
    return shadowlab::kExitUsage;  // CLI11's own codes (105-109 and others) are not ours
  }

  if (*render_cmd) return shadowlab::run_render(render);
  if (*check_cmd) return shadowlab::run_check(check);
  if (*bench_cmd) return bench.placement_only ? shadowlab::run_placement_bench(bench) : shadowlab::run_bench(bench);
  if (*grade_cmd) return shadowlab::run_grade(grade);
  if (*labs_cmd) return shadowlab::run_list_labs(labs.params, labs.json, labs.presets);
  return shadowlab::run_window(window_options);
}
