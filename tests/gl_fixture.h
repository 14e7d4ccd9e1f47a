// One headless EGL context for all GL tests of a binary. Without one the tests fail (not skip): CI has
// Mesa's llvmpipe, so a missing context is a real fault to report.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "renderer/context.h"

namespace shadowlab {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (context_) return;
    std::string error;
    context_ = HeadlessContext::create(&error);
    if (!context_) error_ = error;
  }
  void SetUp() override { ASSERT_TRUE(context_) << error_; }
  // A test leaves no GL error behind: one left pending would fail whichever test next reads
  // glGetError (which test that is depends on the order and the shard), so it fails here, named.
  // MESA_DEBUG=1 prints the call that raised it.
  void TearDown() override {
    if (!context_) return;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
      ADD_FAILURE() << "this test left GL error 0x" << std::hex << e << " pending (MESA_DEBUG=1 names the call)";
  }
  static inline std::unique_ptr<HeadlessContext> context_;
  static inline std::string error_;
};

}  // namespace shadowlab
