// The OpenGL context of a GL exercise's host (lab 0's depth framebuffer): made inside the grading
// sandbox before the host confines itself, and current from then on, so that the student's functions
// call real OpenGL. A headless 3.3 core context on Mesa's surfaceless EGL platform (llvmpipe, one thread,
// no shader cache on disk: grading/cpp_exercise.cpp sets LP_NUM_THREADS=0 and MESA_SHADER_CACHE_DISABLE),
// as the renderer's own headless runs get first (renderer/context.cpp).
#pragma once

namespace shadowlab {

// False (reason on stderr) where no context can be made. Makes one GL call, so that libepoxy has loaded
// the system's OpenGL library before the host may no longer open files.
bool make_exercise_gl_context();

// A program of a vertex and a fragment shader, compiled and linked in the host's context (the probes the
// hosts draw with); no error check: a host's own shaders are fixed text.
unsigned compile_exercise_program(const char* vertex, const char* fragment);

}  // namespace shadowlab
