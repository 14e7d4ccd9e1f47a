// GL contexts. The renderer never knows which one it runs in: the app makes a GLFW window (GLX), and
// headless runs make an EGL context with no surface at all, rendering into framebuffer objects.
#pragma once

#include <memory>
#include <string>

namespace shadowlab {

struct GlInfo {
  std::string vendor, renderer, version, glsl_version;
  int major = 0, minor = 0;
};

// Reads GL_VENDOR etc. from the current context.
GlInfo query_gl_info();

// Enables KHR_debug output to stderr (debug builds ask for it; harmless when not available).
void enable_gl_debug_output();

class HeadlessContext {
 public:
  // Tries Mesa's surfaceless platform, then the EGL device platform; asks for the highest core
  // version (4.6 down to 3.3). On failure returns null and says what was tried and what to install.
  static std::unique_ptr<HeadlessContext> create(std::string* error);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  const std::string& platform() const { return platform_; }

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string platform_;
};

}  // namespace shadowlab
