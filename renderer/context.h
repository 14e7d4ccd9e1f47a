// GL contexts. The renderer never knows which one it runs in: the app makes a GLFW window, and headless
// runs make an EGL context with no surface at all (Linux, built with SHADOWLAB_EGL), or else a hidden
// GLFW window (Windows, macOS, a Linux build without EGL: these need a display, e.g. Xvfb on a server),
// rendering into framebuffer objects either way.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

struct GlInfo {
  std::string vendor, renderer, version, glsl_version;
  int major = 0, minor = 0;
};

// Reads GL_VENDOR etc. from the current context.
GlInfo query_gl_info();

// Enables KHR_debug output to stderr (debug builds ask for it; harmless when not available).
void enable_gl_debug_output();

// "OpenGL 4.5 core, llvmpipe (LLVM 15.0.6, 256 bits)" for the current context.
std::string gl_summary();
// What runs differently on the current context than on OpenGL 4.3 and up, one sentence each; empty when
// nothing does. The course's floor is 3.3 core; macOS stops at 4.1 (no compute shaders, no KHR_debug).
std::vector<std::string> gl_fallbacks();

// GLFW reports errors through a callback: this one keeps the last message (per thread) so that a
// failure can say why ("X11: The DISPLAY environment variable is missing"). Installed by
// HeadlessContext and the window; take_glfw_error() returns the message and clears it.
void capture_glfw_errors();
std::string take_glfw_error();

class HeadlessContext {
 public:
  // With EGL: tries Mesa's surfaceless platform, then the EGL device platform. Then (or without EGL) a
  // hidden 1x1 GLFW window. Asks for the highest core version (4.6 down to 3.3). On failure returns
  // null and says what was tried and what to install.
  static std::unique_ptr<HeadlessContext> create(std::string* error);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  const std::string& platform() const { return platform_; }

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;  // EGL
  void* context_ = nullptr;
  void* window_ = nullptr;   // GLFW (the hidden window's context)
  std::string platform_;
};

}  // namespace shadowlab
