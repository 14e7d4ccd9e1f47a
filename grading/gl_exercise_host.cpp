#include "grading/gl_exercise_host.h"

#include <cstdio>
#include <utility>

#include "renderer/gl.h"
// EGL straight from libEGL after epoxy, as renderer/context.cpp includes it.
#include <EGL/egl.h>
#include <EGL/eglext.h>

namespace shadowlab {

bool make_exercise_gl_context() {
  const EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor) || !eglBindAPI(EGL_OPENGL_API)) {
    std::fprintf(stderr, "exercise host: no EGL surfaceless display (Mesa's libegl-mesa0)\n");
    return false;
  }
  // A surfaceless display offers pbuffer configs only (the default asks for a window).
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = EGL_NO_CONTEXT;
  if (eglChooseConfig(display, config_attribs, &config, 1, &configs) && configs > 0)
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    std::fprintf(stderr, "exercise host: no OpenGL 3.3 core context on EGL\n");
    return false;
  }
  return glGetString(GL_VERSION) != nullptr;
}

unsigned compile_exercise_program(const char* vertex, const char* fragment) {
  const GLuint program = glCreateProgram();
  for (const auto& [type, text] : {std::pair{GL_VERTEX_SHADER, vertex}, std::pair{GL_FRAGMENT_SHADER, fragment}}) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    glAttachShader(program, shader);
    glDeleteShader(shader);
  }
  glLinkProgram(program);
  return program;
}

}  // namespace shadowlab
