// The windowed app: GLFW window, the shared renderer, and the ImGui panel.
#pragma once

#include <string>

namespace shadowlab {

struct WindowOptions {
  int lab = 0;
  std::string scene_file;
};

// Returns the process exit code. Without a display it prints one line naming the headless commands.
int run_window(const WindowOptions& options);

}  // namespace shadowlab
