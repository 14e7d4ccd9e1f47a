// Lab 0's OpenGL part (renderer/shadow_target.h, labs/00_basic_shadow_map/gl_setup.h): the renderer's own
// functions leave the state the lab's check asks for, the driver fact the lab text quotes, and a
// student's file run in the sandbox with its own headless context (grading/cpp_exercise.h, `renders`).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "labs/00_basic_shadow_map/gl_setup.h"
#include "renderer/shader.h"  // data_dir
#include "tests/gl_fixture.h"
#include "grading/cpp_exercise.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

using GlShadowTarget = GlTest;

GLint texture_parameter(GLuint texture, GLenum name) {
  GLint value = 0;
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexParameteriv(GL_TEXTURE_2D, name, &value);
  glBindTexture(GL_TEXTURE_2D, 0);
  return value;
}

TEST_F(GlShadowTarget, SolutionLeavesTheCourseState) {
  glViewport(0, 0, 640, 480);
  const ShadowTarget target = create_shadow_target(96, GL_DEPTH_COMPONENT32F);
  GLint bound = -1;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  EXPECT_EQ(bound, 0) << "create_shadow_target gives the window its framebuffer back";
  EXPECT_EQ(texture_parameter(target.depth_texture, GL_TEXTURE_MIN_FILTER), GL_NEAREST);
  EXPECT_EQ(texture_parameter(target.depth_texture, GL_TEXTURE_MAG_FILTER), GL_NEAREST);
  EXPECT_EQ(texture_parameter(target.depth_texture, GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(texture_parameter(target.depth_texture, GL_TEXTURE_WRAP_T), GL_CLAMP_TO_EDGE);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glClearDepth(kStainDepth);
  glClear(GL_DEPTH_BUFFER_BIT);
  glClearDepth(1.0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  begin_shadow_pass(target);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 96);
  EXPECT_EQ(viewport[3], 96);
  float depth = 0.0f;
  glReadPixels(95, 95, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_EQ(depth, 1.0f) << "the pass clears the stained map to the far plane";
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &target.framebuffer);
  glDeleteTextures(1, &target.depth_texture);
}

// The fact the lab text quotes: Mesa (which implements a later OpenGL than 3.3, where the draw-buffer
// rule of completeness was dropped) calls a depth-only framebuffer complete without glDrawBuffer(GL_NONE).
TEST_F(GlShadowTarget, MesaCompleteWithoutDrawBufferNone) {
  GLuint texture = 0, framebuffer = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture, 0);
  GLint draw_buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
  EXPECT_EQ(draw_buffer, GL_COLOR_ATTACHMENT0) << "a new framebuffer draws to its first colour attachment";
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE))
      << "the lab text (labs/00_basic_shadow_map/README.md, step 5) says Mesa reports this complete";
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
}

// A file of the corpus run in the sandbox, as lab 0's check runs it.
TargetState run_in_sandbox(const fs::path& file) {
  CppExerciseSpec spec;
  spec.source = file;
  spec.display_name = "labs/00_basic_shadow_map/gl_shadow_target.cpp";
  spec.host = "00_basic_shadow_map";
  spec.headers = {"labs/00_basic_shadow_map/gl_setup.h", "renderer/shadow_target.h", "renderer/gl.h"};
  spec.renders = true;
  CppExercise program(spec);
  return program.call<TargetState>(TargetCall{300, 1280, 720});
}

TEST(GlExerciseSandbox, SolutionAndAWrongAnswerRunWithTheirOwnContext) {
  if (const std::string why = cpp_exercise_unavailable("00_basic_shadow_map"); !why.empty()) GTEST_SKIP() << why;
  const TargetState right = run_in_sandbox(data_dir() / "renderer/shadow_target.cpp");
  EXPECT_EQ(right.status, GL_FRAMEBUFFER_COMPLETE);
  EXPECT_EQ(right.depth_bits, 24);
  EXPECT_EQ(right.wrap_s, GL_CLAMP_TO_EDGE);
  EXPECT_EQ(right.viewport[2], 300);
  EXPECT_EQ(right.depth_min, 1.0f);
  EXPECT_EQ(right.draw_buffer, GL_NONE);
  const TargetState repeat =
      run_in_sandbox(data_dir() / "tests/answers/00_basic_shadow_map/wrong/repeat_wrap__gl_shadow_target.cpp");
  EXPECT_EQ(repeat.status, GL_FRAMEBUFFER_COMPLETE);
  EXPECT_EQ(repeat.wrap_s, GL_REPEAT);
  // What the lit pass reads (kProbeUv): the solution the far plane beyond the right edge beside the open
  // quarter, a repeating map the occluder from the other side (both within a 24-bit step).
  EXPECT_NEAR(right.probe_reads[2], 1.0f, 1.0 / 16777215.0);
  EXPECT_NEAR(repeat.probe_reads[2], kOccluderDepth, 1.0 / 16777215.0);
  EXPECT_NEAR(right.probe_reads[0], kOccluderDepth, 1.0 / 16777215.0);
  const TargetState uncleared =
      run_in_sandbox(data_dir() / "tests/answers/00_basic_shadow_map/wrong/no_clear__gl_shadow_target.cpp");
  // The stain as the 24-bit map stores it: within one step of 2^-24 (0.25 reads back as 0.25000003 here).
  EXPECT_NEAR(uncleared.depth_max, kStainDepth, 1.0 / 16777215.0) << "the host's stain stays where the pass does not clear";
  EXPECT_EQ(uncleared.depth_min, uncleared.depth_max);
}

TEST(GlExerciseSandbox, ReadingAFileKillsOnlyTheExercise) {
  if (const std::string why = cpp_exercise_unavailable("00_basic_shadow_map"); !why.empty()) GTEST_SKIP() << why;
  try {
    run_in_sandbox(data_dir() / "tests/answers/00_basic_shadow_map/wrong/reads_files__gl_shadow_target.cpp");
    FAIL() << "a file was opened from inside the confined host";
  } catch (const ExerciseError& e) {
    EXPECT_EQ(e.status(), "crashed") << e.what();
    EXPECT_NE(std::string(e.what()).find("SIGSYS"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowlab
