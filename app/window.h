// The windowed app: GLFW window, the shared renderer, and the ImGui panel.
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

struct WindowOptions {
  int lab = 0;
  std::string scene_file;
  // As `render` takes them: a preset and parameter values over the lab's (and its saved settings'), the
  // implementation shown, the camera ("eye=x,y,z target=x,y,z fov=deg"), the window's size in pixels.
  // All of them are for this run: none is saved unless the user changes it in the window (see
  // OneOffValues, app/settings.h).
  std::string preset;
  std::vector<std::string> assignments;
  std::string impl = "exercise";
  std::string camera;
  std::string size;  // "WxH"; empty: 1440x860
  // For tests and documentation: quit after this many frames (0: run until closed), saving the last
  // frame, panel included, to `screenshot` if given.
  int frames = 0;
  std::string screenshot;
  // Scripted input (app/input_script.h): key presses through ImGui's GLFW callback, frames, screenshots,
  // resizing and minimising; the window closes when it ends.
  std::string script;
  // The bench.json shown in the Speed against error window (opened at start when given). Empty: the
  // project's measured docs/bench.json, loaded when the window is first opened.
  std::string bench_file;
  // Written when the window closes: what the interactive frames cost (frame times, and the glFinish
  // calls and blocking query reads with the pass-time line shown and hidden). For tests and benchmarks.
  std::string frame_report;
};

// Returns the process exit code. Without a display it prints one line naming the headless commands.
int run_window(const WindowOptions& options);

}  // namespace shadowlab
