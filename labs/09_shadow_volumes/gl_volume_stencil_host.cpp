// main() of lab 9's GL exercise when grading builds it (grading/cpp_exercise.h, `renders`): a headless
// OpenGL context first, then each VolumeCall is answered with the three passes of gl_volume_setup.h's
// scene run through stencil_pass and begin_additive_lit_pass, and the state they left
// (labs/09_shadow_volumes/gl_volume_setup.h). Not part of the shadowlab binary.
#include "labs/09_shadow_volumes/gl_volume_setup.h"
#include "grading/cpp_exercise_host.h"
#include "grading/gl_exercise_host.h"

namespace {

using namespace shadowlab;

// A quad over one column at an NDC depth, counter-clockwise on screen (front) or clockwise (back), in a
// colour; w = 1, so a depth beyond 1 is clipped unless depth is clamped.
constexpr const char* kVertex =
    "#version 330 core\nuniform float u_x0, u_x1, u_z;\nuniform bool u_front;\n"
    "void main() {\n"
    "  int i = u_front ? gl_VertexID : (gl_VertexID == 1 ? 2 : gl_VertexID == 2 ? 1 : gl_VertexID);\n"
    "  gl_Position = vec4((i & 1) == 0 ? u_x0 : u_x1, (i & 2) == 0 ? -1.0 : 1.0, u_z, 1.0);\n"
    "}\n";
constexpr const char* kFragment =
    "#version 330 core\nuniform vec4 u_colour;\nout vec4 colour;\nvoid main() { colour = u_colour; }\n";

struct Scene {
  GLuint program = 0, vao = 0, colour = 0, depth_stencil = 0, framebuffer = 0;
};

Scene make_scene() {
  Scene s;
  s.program = compile_exercise_program(kVertex, kFragment);
  glGenVertexArrays(1, &s.vao);
  glGenRenderbuffers(1, &s.colour);
  glBindRenderbuffer(GL_RENDERBUFFER, s.colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kVolumeColumns, 1);
  glGenRenderbuffers(1, &s.depth_stencil);
  glBindRenderbuffer(GL_RENDERBUFFER, s.depth_stencil);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kVolumeColumns, 1);
  glGenFramebuffers(1, &s.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, s.colour);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, s.depth_stencil);
  return s;
}

void draw_quad(const Scene& s, int column, float z, bool front, float red) {
  const float width = 2.0f / kVolumeColumns;
  glUniform1f(glGetUniformLocation(s.program, "u_x0"), -1.0f + width * static_cast<float>(column));
  glUniform1f(glGetUniformLocation(s.program, "u_x1"), -1.0f + width * static_cast<float>(column + 1));
  glUniform1f(glGetUniformLocation(s.program, "u_z"), z);
  glUniform1i(glGetUniformLocation(s.program, "u_front"), front ? 1 : 0);
  glUniform4f(glGetUniformLocation(s.program, "u_colour"), red, 0.0f, 1.0f, 1.0f);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

void draw_receivers(const Scene& s, float red) {
  for (int c = 0; c < kVolumeColumns; ++c) draw_quad(s, c, kReceiverZ, true, red);
}

// The state a renderer's frame has between passes (LitPass::end's), and the window's stencil stained.
void reset_state() {
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_CULL_FACE);
  glStencilMask(0xFF);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
}

bool wraps(GLint op) { return op != GL_INCR && op != GL_DECR; }

// The counting pass's state as draw_volumes sees it; the first call's is kept, GL_INCR / GL_DECR of any.
void read_pass_state(VolumeState& s) {
  const GLenum front[3] = {GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS};
  const GLenum back[3] = {GL_STENCIL_BACK_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS};
  GLint ops[2][3] = {};
  for (int i = 0; i < 3; ++i) {
    glGetIntegerv(front[i], &ops[0][i]);
    glGetIntegerv(back[i], &ops[1][i]);
  }
  for (const auto& side : ops)
    for (GLint op : side) s.non_wrapping_ops += !wraps(op);
  if (s.draws++ > 0) return;
  for (int i = 0; i < 3; ++i) {
    s.front_ops[i] = ops[0][i];
    s.back_ops[i] = ops[1][i];
  }
  s.stencil_test = glIsEnabled(GL_STENCIL_TEST);
  glGetIntegerv(GL_STENCIL_FUNC, &s.stencil_func);
  glGetIntegerv(GL_STENCIL_REF, &s.stencil_ref);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &s.stencil_value_mask);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &s.stencil_writemask);
  GLboolean mask[4] = {}, depth = GL_FALSE;
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  for (int i = 0; i < 4; ++i) s.colour_writemask[i] = mask[i];
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth);
  s.depth_writemask = depth;
  s.depth_test = glIsEnabled(GL_DEPTH_TEST);
  glGetIntegerv(GL_DEPTH_FUNC, &s.depth_func);
  s.depth_clamp = glIsEnabled(GL_DEPTH_CLAMP);
  s.cull_face = glIsEnabled(GL_CULL_FACE);
  GLint stencil = -1;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_INT, &stencil);
  s.stencil_at_first_draw = stencil;
}

void read_lit_state(VolumeState& s) {
  s.lit_stencil_test = glIsEnabled(GL_STENCIL_TEST);
  glGetIntegerv(GL_STENCIL_FUNC, &s.lit_stencil_func);
  glGetIntegerv(GL_STENCIL_REF, &s.lit_stencil_ref);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &s.lit_stencil_value_mask);
  s.lit_depth_test = glIsEnabled(GL_DEPTH_TEST);
  glGetIntegerv(GL_DEPTH_FUNC, &s.lit_depth_func);
  GLboolean depth = GL_FALSE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth);
  s.lit_depth_writemask = depth;
  s.blend = glIsEnabled(GL_BLEND);
  glGetIntegerv(GL_BLEND_SRC_RGB, &s.blend_src_rgb);
  glGetIntegerv(GL_BLEND_DST_RGB, &s.blend_dst_rgb);
}

VolumeState answer(const VolumeCall& call) {
  VolumeState s;
  const Scene scene = make_scene();
  glViewport(0, 0, kVolumeColumns, 1);
  glUseProgram(scene.program);
  glBindVertexArray(scene.vao);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  // 1. The ambient pass (the host's): colour and depth; a last frame's counts in the stencil.
  reset_state();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearStencil(kStainStencil);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  draw_receivers(scene, kAmbientShare);
  while (glGetError() != GL_NO_ERROR) {
  }
  // 2. The student's counting pass over the volumes' faces, in kVolumeFaces's order.
  stencil_pass(call.z_fail != 0, [&] {
    read_pass_state(s);
    for (const VolumeFace& f : kVolumeFaces) draw_quad(scene, f.column, f.z, f.front, 1.0f);
  });
  s.gl_error_after_pass = static_cast<int>(glGetError());
  GLboolean mask[4] = {};
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  for (int i = 0; i < 4; ++i) s.colour_writemask_after[i] = mask[i];
  s.depth_clamp_after = glIsEnabled(GL_DEPTH_CLAMP);
  s.cull_face_after = glIsEnabled(GL_CULL_FACE);
  glReadPixels(0, 0, kVolumeColumns, 1, GL_STENCIL_INDEX, GL_INT, s.counts);
  // 3. The student's lit pass state, then the receivers again with the light's share.
  while (glGetError() != GL_NO_ERROR) {
  }
  begin_additive_lit_pass();
  s.gl_error_after_lit = static_cast<int>(glGetError());
  read_lit_state(s);
  draw_receivers(scene, kLightShare);
  reset_state();
  unsigned char pixels[kVolumeColumns][4] = {};
  glReadPixels(0, 0, kVolumeColumns, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  for (int c = 0; c < kVolumeColumns; ++c) s.red[c] = pixels[c][0];
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &scene.framebuffer);
  glDeleteRenderbuffers(1, &scene.colour);
  glDeleteRenderbuffers(1, &scene.depth_stencil);
  glDeleteVertexArrays(1, &scene.vao);
  glDeleteProgram(scene.program);
  return s;
}

}  // namespace

int main() { return serve_exercise<VolumeCall, VolumeState>(answer, make_exercise_gl_context); }
