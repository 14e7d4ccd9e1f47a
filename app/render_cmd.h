// `shadowlab render`: one frame headless, with the renderer the window uses; only the context differs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/light.h"
#include "core/params.h"
#include "core/scene.h"

namespace shadowlab {

struct Lab;

struct RenderOptions {
  int lab = 0;
  std::string scene_file;  // empty: the built-in default scene
  std::string preset;                    // --preset NAME: one of the lab's presets, under --set
  std::vector<std::string> assignments;  // --set key=value
  std::string camera;  // --camera "eye=x,y,z target=x,y,z fov=deg" (empty: the scene framed)
  int width = 1280;
  int height = 720;
  std::string out_dir;
  bool buffers = false;
  std::string impl = "solution";
  std::string shadow_test;  // --shadow-test NAME: this registered shadow test instead of the lab's (empty: the lab's)
  // Draw the window's panel (the same code, ImGui offscreen) over final.png, for reproducible
  // documentation pictures; with panel_check the lab's Check runs first and its result is shown.
  bool panel = false;
  bool panel_check = false;
  std::string bench_file;  // with panel: the Speed against error window on this bench.json
  bool penumbra = false;   // with panel: the Penumbra error window, measured on this frame
  float ui_scale = 1.0f;   // with panel: the text and widget scale (2: as on a 200 % monitor)
};

// Exit codes (app/exit_codes.h): 0 written; 2 the command line cannot be used as given; 3 runtime error.
int run_render(const RenderOptions& options);
}  // namespace shadowlab
