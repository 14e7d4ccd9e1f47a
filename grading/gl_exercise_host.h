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

// A program of a vertex and a fragment shader from their texts, for a host's probe draws (the host's own
// GLSL, never the student's); 0-named uniforms and a failed link show in the probe's reads.
unsigned compile_exercise_program(const char* vertex, const char* fragment);

// How the texture bound to GL_TEXTURE_2D is sampled, read back with glGetTexParameter*: its min and mag
// filters, S and T wraps and border colour (the state the course's mistakes set wrong).
void read_texture_sampling(int& min_filter, int& mag_filter, int& wrap_s, int& wrap_t, float* border);

}  // namespace shadowlab
