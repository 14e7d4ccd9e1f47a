// Lab 9's OpenGL part (renderer/volume_stencil.h, labs/09_shadow_volumes/gl_volume_setup.h): the
// renderer's own functions leave the state the lab's check asks for, and students' files run in the
// sandbox with their own headless context give the counts and pictures the lab text describes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "labs/09_shadow_volumes/gl_volume_setup.h"
#include "renderer/shader.h"  // data_dir
#include "tests/gl_fixture.h"
#include "grading/cpp_exercise.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

using GlVolumeStencil = GlTest;

GLint integer(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}

TEST_F(GlVolumeStencil, SolutionLeavesTheCourseState) {
  // A framebuffer with a stencil buffer to clear (the headless context has no window's).
  GLuint buffers[2] = {}, framebuffer = 0;
  glGenRenderbuffers(2, buffers);
  glBindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  glBindRenderbuffer(GL_RENDERBUFFER, buffers[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 4, 4);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, buffers[1]);
  int calls = 0;
  stencil_pass(true, [&] {
    ++calls;
    GLboolean colour[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE}, depth = GL_TRUE;
    glGetBooleanv(GL_COLOR_WRITEMASK, colour);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth);
    EXPECT_FALSE(colour[0] || colour[1] || colour[2] || colour[3]);
    EXPECT_FALSE(depth);
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_CLAMP)) << "z-fail keeps the far caps beyond the far plane";
    EXPECT_EQ(integer(GL_STENCIL_FUNC), GL_ALWAYS);
    EXPECT_EQ(integer(GL_STENCIL_BACK_PASS_DEPTH_FAIL), GL_INCR_WRAP);
    EXPECT_EQ(integer(GL_STENCIL_PASS_DEPTH_FAIL), GL_DECR_WRAP);
    EXPECT_EQ(integer(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
  });
  EXPECT_EQ(calls, 1);
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_CLAMP));
  stencil_pass(false, [&] {
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_CLAMP));
    EXPECT_EQ(integer(GL_STENCIL_PASS_DEPTH_PASS), GL_INCR_WRAP);
    EXPECT_EQ(integer(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_DECR_WRAP);
  });
  begin_additive_lit_pass();
  EXPECT_EQ(integer(GL_STENCIL_FUNC), GL_EQUAL);
  EXPECT_EQ(integer(GL_STENCIL_REF), 0);
  EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_EQUAL);
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_ONE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteRenderbuffers(2, buffers);
}

// A file run in the sandbox as lab 9's check runs it: z-pass, then z-fail.
std::vector<VolumeState> run_volume_sandbox(const fs::path& file) {
  CppExerciseSpec spec;
  spec.source = file;
  spec.display_name = "labs/09_shadow_volumes/gl_volume_stencil.cpp";
  spec.host = "09_shadow_volumes";
  spec.headers = {"labs/09_shadow_volumes/gl_volume_setup.h", "renderer/volume_stencil.h", "renderer/gl.h"};
  spec.renders = true;
  CppExercise program(spec);
  return program.call_many<VolumeState>(std::vector<VolumeCall>{{0}, {1}});
}

fs::path answer(const std::string& kind, const std::string& name) {
  return data_dir() / "tests/answers/09_shadow_volumes" / kind / (name + "__gl_volume_stencil.cpp");
}

TEST(GlVolumeSandbox, SolutionCountsTheVolumesAroundEachReceiver) {
  if (const std::string why = cpp_exercise_unavailable("09_shadow_volumes"); !why.empty()) GTEST_SKIP() << why;
  const std::vector<VolumeState> states = run_volume_sandbox(data_dir() / "renderer/volume_stencil.cpp");
  const VolumeState &zpass = states[0], &zfail = states[1];
  for (int c = 0; c < kVolumeColumns; ++c) {
    EXPECT_EQ(zfail.counts[c], kInsideVolumes[c]) << "z-fail, column " << c;
    if (kZPassGraded[c]) {
      EXPECT_EQ(zpass.counts[c], kInsideVolumes[c]) << "z-pass, column " << c;
    }
    // Ambient 0.25 -> 64 of 255, plus the light's 0.5 -> 128 (each pass rounds its own share): 192, one
    // step above 0.75's 191 (measured here; the check's one-step tolerance, kRedTolerance).
    EXPECT_EQ(zfail.red[c], kInsideVolumes[c] == 0 ? 192 : 64) << "z-fail picture, column " << c;
  }
  EXPECT_EQ(zpass.counts[6], 0) << "z-pass misses the volume the eye is in: the lab text's failure";
  EXPECT_EQ(zpass.stencil_at_first_draw, 0);
  EXPECT_EQ(zpass.draws, 1);
}

TEST(GlVolumeSandbox, WrongAnswersShowInTheCounts) {
  if (const std::string why = cpp_exercise_unavailable("09_shadow_volumes"); !why.empty()) GTEST_SKIP() << why;
  // GL_INCR / GL_DECR: a -1 drawn first sticks at 0 (z-pass column 1, z-fail column 4) and its +1 makes 1.
  const std::vector<VolumeState> saturating = run_volume_sandbox(answer("wrong", "incr_not_wrap"));
  EXPECT_EQ(saturating[0].counts[1], 1);
  EXPECT_EQ(saturating[0].counts[2], 0) << "the other order comes out right";
  EXPECT_EQ(saturating[1].counts[4], 1);
  EXPECT_GT(saturating[0].non_wrapping_ops, 0);
  // No depth clamp: the far cap beyond the far plane is clipped, and its +1 with it.
  const std::vector<VolumeState> unclamped = run_volume_sandbox(answer("wrong", "no_depth_clamp"));
  EXPECT_EQ(unclamped[1].counts[3], 0);
  EXPECT_EQ(unclamped[1].counts[7], 1);
  // The negated counts (front and back swapped) are right: 0 stays 0, one volume reads 255.
  const std::vector<VolumeState> negated = run_volume_sandbox(answer("right", "negated_counts_lequal"));
  EXPECT_EQ(negated[1].counts[3], 255);
  EXPECT_EQ(negated[1].counts[0], 0);
  EXPECT_EQ(negated[1].red[3], 64);
}

}  // namespace
}  // namespace shadowlab
