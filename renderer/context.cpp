#include "renderer/context.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include "renderer/gl.h"
// EGL straight from libEGL, not through epoxy: epoxy's EGL dispatch aborts on eglGetPlatformDisplay
// before a display exists (see shared/NOTES.md). Included after epoxy so GL types are not redefined.
#include <EGL/egl.h>
#include <EGL/eglext.h>

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

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* error) {
#ifdef NDEBUG
  const bool debug = false;
#else
  const bool debug = true;
#endif
  std::string tried;
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
  if (error) {
    *error = "cannot create a headless OpenGL 3.3 core context. Tried:\n" + tried +
             "Install Mesa's EGL and software rasteriser: apt-get install libegl-mesa0 libgl1-mesa-dri "
             "(or run scripts/setup).";
  }
  return nullptr;
}

HeadlessContext::~HeadlessContext() {
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
}

}  // namespace shadowlab
