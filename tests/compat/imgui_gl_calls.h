// Every call of the OpenGL side of the ImGui seam (app/imgui_gl.h), for the compile checks against the
// stand-in headers of ImGui 1.91.9 and 1.92 (imgui_gl_imgui191.cpp, imgui_seam_imgui192.cpp).
#pragma once

#include "app/imgui_gl.h"

namespace shadowlab {

inline void every_gl_call_of_the_seam(unsigned gl_name) {
  gl_image(gl_name, ImVec2(64, 64));
  gl_image(gl_name, ImVec2(64, 64), ImVec2(0, 1), ImVec2(1, 0));
  remake_font_texture();
  drop_font_texture();
}

}  // namespace shadowlab
