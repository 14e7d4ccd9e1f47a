#include "renderer/context.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include "renderer/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#if SHADOWLAB_HAS_EGL
// EGL straight from libEGL, not through epoxy: epoxy's EGL dispatch aborts on eglGetPlatformDisplay
// before a display exists (see shared/NOTES.md). Included after epoxy so GL types are not redefined.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

namespace shadowlab {

GlInfo query_gl_info() {
  auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  GlInfo info{str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION), str(GL_SHADING_LANGUAGE_VERSION)};
  glGetIntegerv(GL_MAJOR_VERSION, &info.major);
  glGetIntegerv(GL_MINOR_VERSION, &info.minor);
  return info;
}

namespace {
void GLAPIENTRY debug_callback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                               const void*) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  std::fprintf(stderr, "GL %s: %s\n", type == GL_DEBUG_TYPE_ERROR ? "error" : "debug", message);
}
}  // namespace

void enable_gl_debug_output() {
  if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debug_callback, nullptr);
}

std::string gl_summary() {
  const GlInfo info = query_gl_info();
  GLint mask = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  const char* profile = (mask & GL_CONTEXT_CORE_PROFILE_BIT) ? "core" : (mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) ? "compatibility" : "";
  return "OpenGL " + std::to_string(info.major) + "." + std::to_string(info.minor) + (*profile ? " " : "") + profile + ", " +
         info.renderer;
}

std::vector<std::string> gl_fallbacks() {
  std::vector<std::string> out;
  const int version = epoxy_gl_version();
  if (version < 43)
    out.push_back("no compute shaders (OpenGL 4.3): the fast moments blur (vsm.blur_method=fast) runs as fragment-shader "
                  "passes, same moments, slower; the taught blur is unchanged");
  if (version < 43 && !epoxy_has_gl_extension("GL_KHR_debug"))
    out.push_back("no KHR_debug: debug builds print no GL debug messages");
  return out;
}

namespace {
thread_local std::string glfw_error;
}  // namespace

void capture_glfw_errors() {
  glfwSetErrorCallback([](int code, const char* description) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%05X", code);
    glfw_error = std::string(description ? description : "unknown error") + " (GLFW error " + hex + ")";
  });
}

std::string take_glfw_error() {
  std::string e = std::move(glfw_error);
  glfw_error.clear();
  return e;
}

#if SHADOWLAB_HAS_EGL
namespace {

struct Attempt {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string name;
};

EGLDisplay device_platform_display() {
  auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!query_devices) return EGL_NO_DISPLAY;
  EGLDeviceEXT devices[8];
  EGLint count = 0;
  if (!query_devices(8, devices, &count) || count == 0) return EGL_NO_DISPLAY;
  return eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
}

EGLContext create_core_context(EGLDisplay display, bool debug) {
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &n) || n == 0) {
    // Surfaceless displays may offer no pbuffer configs; with KHR_no_config_context none is needed.
    config = nullptr;
  }
  const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
  for (const auto& v : versions) {
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, v[0],
                              EGL_CONTEXT_MINOR_VERSION, v[1],
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                              EGL_NONE};
    EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
    if (ctx != EGL_NO_CONTEXT) return ctx;
  }
  return EGL_NO_CONTEXT;
}

}  // namespace
#endif  // SHADOWLAB_HAS_EGL

namespace {

// A hidden 1x1 window whose context renders into framebuffer objects: headless where EGL is not
// (Windows, macOS, Linux builds without EGL). Needs a display (Xvfb on a Linux server).
GLFWwindow* hidden_glfw_window(bool debug, std::string* why) {
  capture_glfw_errors();
  take_glfw_error();
  if (!glfwInit()) {
    *why = take_glfw_error();
    return nullptr;
  }
  const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
  for (const auto& v : versions) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v[0]);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v[1]);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // macOS gives a core context only so
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    if (GLFWwindow* w = glfwCreateWindow(1, 1, "shadowlab (headless)", nullptr, nullptr)) {
      take_glfw_error();  // the versions refused before this one
      return w;
    }
  }
  *why = take_glfw_error();
  glfwTerminate();
  return nullptr;
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* error) {
#ifdef NDEBUG
  const bool debug = false;
#else
  const bool debug = true;
#endif
  std::string tried;
#if SHADOWLAB_HAS_EGL
  const Attempt attempts[] = {
      {eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), "EGL surfaceless (Mesa)"},
      {device_platform_display(), "EGL device platform"},
  };
  for (const auto& attempt : attempts) {
    if (attempt.display == EGL_NO_DISPLAY) {
      tried += "  " + attempt.name + ": no display\n";
      continue;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(attempt.display, &major, &minor)) {
      tried += "  " + attempt.name + ": eglInitialize failed\n";
      continue;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      tried += "  " + attempt.name + ": desktop OpenGL API not available\n";
      eglTerminate(attempt.display);
      continue;
    }
    EGLContext ctx = create_core_context(attempt.display, debug);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(attempt.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      tried += "  " + attempt.name + ": no OpenGL 3.3+ core context (eglCreateContext/eglMakeCurrent failed)\n";
      if (ctx != EGL_NO_CONTEXT) eglDestroyContext(attempt.display, ctx);
      eglTerminate(attempt.display);
      continue;
    }
    std::unique_ptr<HeadlessContext> result(new HeadlessContext());
    result->display_ = attempt.display;
    result->context_ = ctx;
    result->platform_ = attempt.name;
    if (debug) enable_gl_debug_output();
    return result;
  }
#endif
  std::string why;
  if (GLFWwindow* window = hidden_glfw_window(debug, &why)) {
    glfwMakeContextCurrent(window);
    std::unique_ptr<HeadlessContext> result(new HeadlessContext());
    result->window_ = window;
    result->platform_ = "hidden GLFW window";
    if (debug) enable_gl_debug_output();
    return result;
  }
  tried += "  hidden GLFW window: " + (why.empty() ? std::string("no OpenGL 3.3+ core context") : why) + "\n";
  if (error) {
    *error = "cannot create a headless OpenGL 3.3 core context. Tried:\n" + tried +
#if SHADOWLAB_HAS_EGL
             "Install Mesa's EGL and software rasteriser: apt-get install libegl-mesa0 libgl1-mesa-dri "
             "(or run scripts/setup).";
#else
             "This build has no EGL (SHADOWLAB_EGL=OFF): headless runs need a display; on a Linux server "
             "run under Xvfb (xvfb-run -a shadowlab ...).";
#endif
  }
  return nullptr;
}

HeadlessContext::~HeadlessContext() {
  if (window_) {
    glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(static_cast<GLFWwindow*>(window_));
    glfwTerminate();
    return;
  }
#if SHADOWLAB_HAS_EGL
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
#endif
}

}  // namespace shadowlab
