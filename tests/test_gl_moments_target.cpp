// Lab 3's OpenGL part (renderer/moments_target.h, labs/03_vsm_setup/gl_setup.h): the renderer's own
// functions leave the state the lab's check asks for, and files of the corpus run in the sandbox with
// their own headless context show each mistake in the probe's reads (grading/cpp_exercise.h, `renders`).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>

#include "labs/03_vsm_setup/gl_setup.h"
#include "renderer/shader.h"  // data_dir
#include "tests/gl_fixture.h"
#include "grading/cpp_exercise.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;
using namespace moments_probe;

using GlMomentsTarget = GlTest;

TEST_F(GlMomentsTarget, SolutionLeavesTheCourseState) {
  glViewport(0, 0, 640, 480);
  const MomentsTarget target = create_moments_target(96);
  GLint bound = -1;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  EXPECT_EQ(bound, 0) << "create_moments_target gives the window its framebuffer back";
  glBindTexture(GL_TEXTURE_2D, target.moments_texture);
  for (const auto& [name, expected] : {std::pair{GL_TEXTURE_MIN_FILTER, GL_LINEAR}, std::pair{GL_TEXTURE_MAG_FILTER, GL_LINEAR},
                                       std::pair{GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE}, std::pair{GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE}}) {
    GLint value = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, name, &value);
    EXPECT_EQ(value, expected) << "parameter 0x" << std::hex << name;
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  GLint format = 0;
  glBindRenderbuffer(GL_RENDERBUFFER, target.depth_renderbuffer);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
  EXPECT_EQ(format, GL_DEPTH_COMPONENT24);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glClearBufferfv(GL_COLOR, 0, kStainMoments);
  glClearBufferfv(GL_DEPTH, 0, &moments_probe::kStainDepth);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  begin_moments_pass(target);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 96);
  EXPECT_EQ(viewport[3], 96);
  float moments[2] = {0, 0}, depth = 0;
  glReadPixels(95, 95, 1, 1, GL_RG, GL_FLOAT, moments);
  glReadPixels(95, 95, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_EQ(moments[0], 1.0f) << "the pass clears the stained moments to the far plane's (1, 1)";
  EXPECT_EQ(moments[1], 1.0f);
  EXPECT_EQ(depth, 1.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &target.framebuffer);
  glDeleteTextures(1, &target.moments_texture);
  glDeleteRenderbuffers(1, &target.depth_renderbuffer);
}

// A file of the corpus run in the sandbox, as lab 3's check runs it.
MomentsState run_moments_sandbox(const fs::path& file) {
  CppExerciseSpec spec;
  spec.source = file;
  spec.display_name = "labs/03_vsm_setup/gl_moments_target.cpp";
  spec.host = "03_vsm_setup";
  spec.headers = {"labs/03_vsm_setup/gl_setup.h", "renderer/moments_target.h", "renderer/gl.h"};
  spec.renders = true;
  CppExercise program(spec);
  return program.call<MomentsState>(MomentsCall{300, 1280, 720});
}

fs::path wrong_answer(const std::string& name) {
  return data_dir() / ("tests/answers/03_vsm_setup/wrong/" + name + "__gl_moments_target.cpp");
}

// The probe's points (gl_setup.h): 0 is 0.02 behind the near occluder, 4 on its edge.
TEST(GlExerciseSandbox, MomentsMistakesShowInTheProbe) {
  if (const std::string why = cpp_exercise_unavailable("03_vsm_setup"); !why.empty()) GTEST_SKIP() << why;
  const MomentsState right = run_moments_sandbox(data_dir() / "renderer/moments_target.cpp");
  EXPECT_EQ(right.status, GL_FRAMEBUFFER_COMPLETE);
  EXPECT_EQ(right.red_bits, 32);
  EXPECT_EQ(right.depth_bits, 24);
  EXPECT_EQ(right.moments_off_clear, 0.0f);
  // 1e-4 / (1e-4 + 0.02^2) behind the near occluder; the mean of its moments and the clear value's on its edge.
  EXPECT_NEAR(right.probe_bounds[0], 0.2f, 1e-5);
  EXPECT_NEAR(right.probe_moments[4][0], (kNearDepth + 1.0f) / 2.0f, 1e-6);
  // 8-bit moments: the variance behind the occluder is rounding, and the bound another.
  const MomentsState rgba8 = run_moments_sandbox(wrong_answer("rgba8_moments"));
  EXPECT_EQ(rgba8.red_bits, 8);
  EXPECT_GT(std::abs(rgba8.probe_bounds[0] - 0.2f), 0.01f);
  // No depth buffer: the far occluder, drawn second, is what the map holds under the near one.
  const MomentsState no_depth = run_moments_sandbox(wrong_answer("no_depth_buffer"));
  EXPECT_EQ(no_depth.depth_attachment_type, GL_NONE);
  EXPECT_NEAR(no_depth.probe_moments[0][0], kFarDepth, 1e-6);
  // Nearest filtering: the edge reads one texel's moments, the occluder's or the clear value's.
  const MomentsState nearest = run_moments_sandbox(wrong_answer("nearest_filter"));
  EXPECT_TRUE(nearest.probe_moments[4][0] == 1.0f || std::abs(nearest.probe_moments[4][0] - kNearDepth) < 1e-6f)
      << nearest.probe_moments[4][0];
}

}  // namespace
}  // namespace shadowlab
