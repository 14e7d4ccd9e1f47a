// The window's live GL exercises (grading/live_gl.h): each lab's OpenGL file, built into a shared library
// and loaded into this process, is what the renderer then calls. A right answer written differently from
// the solution draws the solution's picture; a wrong one draws another (the course's mistake, visible);
// a file that does not build is refused with the compiler's file:line:col; a lab's file built with
// another lab's name is refused before anything is built.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/scene.h"
#include "grading/lab.h"
#include "grading/live_gl.h"
#include "grading/platform_process.h"
#include "labs/registry.h"
#include "renderer/renderer.h"
#include "renderer/shader.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

struct LiveCase {
  int lab;
  const char* right;  // tests/answers/<lab>/right/<right>__<file>
  const char* wrong;  // tests/answers/<lab>/wrong/<wrong>__<file>
  int min_wrong_pixels;  // at least this many of the 320 x 180 pixels differ from the solution's
};

// Wrong answers whose mistake shows in the lab's own picture at 320 x 180; the floors are half of what
// was measured (the test prints it): lab 0 10,876, lab 3 63, lab 5 113, lab 9 10,879 pixels.
const LiveCase kCases[] = {
    {0, "clamp_to_border_one", "no_clear", 5000},      // never cleared: every point shadowed
    {3, "rgba32f_moments", "no_depth_buffer", 30},     // farther casters overwrite nearer moments
    {5, "y_then_x", "result_left_in_target", 50},      // the lit pass reads the moments blurred along x only
    {9, "two_passes_culling", "lit_depth_less", 5000}, // GL_LESS: no surface of the ambient pass is lit
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class LiveGlTest : public GlTest, public ::testing::WithParamInterface<LiveCase> {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (!platform::grading_unavailable().empty()) GTEST_SKIP() << platform::grading_unavailable();
    dir_ = platform::make_private_temp_dir("shadowlab-live-gl-test");
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
    GlTest::TearDown();
  }
  // The lab's solution picture with `code` in place of the renderer's host functions.
  std::vector<std::uint8_t> picture(const Lab& lab, const GlHostCode& code) {
    Renderer r;
    const Scene scene = make_default_scene();
    r.set_scene(scene);
    Features features = lab.hooks(Impl::Solution);
    features.gl_host = code;
    EXPECT_TRUE(r.set_features(features)) << r.shader_error();
    ParamSet params = lab_params(lab);
    params.set("view.debug_quad", 0.0);
    FrameRequest request;
    request.camera = OrbitCamera::framing(scene.bounds());
    request.width = 320;
    request.height = 180;
    r.render(params, request);
    return r.read_color();
  }
  GlHostCode build(const Lab& lab, const std::string& kind, const std::string& answer) {
    const std::string& file = lab.gl_exercise_files.front();
    const fs::path source = data_dir() / "tests/answers" / fs::path(file).parent_path().filename() / kind /
                            (answer + "__" + fs::path(file).filename().string());
    const fs::path folder = dir_ / (kind + "-" + answer);
    fs::create_directories(folder);
    return build_live_gl_exercise(folder, file, read_text(source));
  }
  fs::path dir_;
};

long differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  long n = 0;
  for (std::size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4)
    n += std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2]) > 6;
  return n;
}

TEST_P(LiveGlTest, RightAnswerDrawsTheSolutionWrongAnswerDoesNot) {
  const LiveCase c = GetParam();
  const Lab& lab = *find_lab(c.lab);
  ASSERT_EQ(lab.gl_exercise_files.size(), 1u);
  ASSERT_TRUE(live_gl_exercise_supported(lab.gl_exercise_files.front()));
  const std::vector<std::uint8_t> own = picture(lab, GlHostCode{});
  const GlHostCode right = build(lab, "right", c.right);
  EXPECT_NE(right, GlHostCode{}) << "the loaded functions are the renderer's own";
  const long right_pixels = differing(picture(lab, right), own);
  const long wrong_pixels = differing(picture(lab, build(lab, "wrong", c.wrong)), own);
  std::printf("lab %d: right answer %s differs in %ld pixels, wrong answer %s in %ld\n", c.lab, c.right, right_pixels,
              c.wrong, wrong_pixels);
  EXPECT_EQ(right_pixels, 0);
  EXPECT_GE(wrong_pixels, c.min_wrong_pixels);
}

INSTANTIATE_TEST_SUITE_P(Labs, LiveGlTest, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return "lab" + std::to_string(info.param.lab); });

TEST_F(LiveGlTest, ABuildErrorNamesTheStudentsLine) {
  const Lab& lab = *find_lab(0);
  const std::string file = lab.gl_exercise_files.front();
  try {
    build_live_gl_exercise(dir_ / "broken", file, read_text(data_dir() / file) + "int broken = ;\n");
    FAIL() << "a file that does not compile was loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find(file + ":"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(": error"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(dir_.string()), std::string::npos) << "the temporary folder shows: " << e.what();
  }
  // A file that leaves out one of its lab's functions is named by the linker (-z defs), not loaded.
  try {
    build_live_gl_exercise(dir_ / "half", file, "#include \"labs/00_basic_shadow_map/gl_setup.h\"\n"
                                                 "namespace shadowlab { void begin_shadow_pass(const ShadowTarget&) {} }\n");
    FAIL() << "a file without create_shadow_target was loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("create_shadow_target"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(live_gl_exercise_supported("labs/02_ortho_fit/exercise.cpp"));
  EXPECT_THROW(build_live_gl_exercise(dir_ / "other", "labs/02_ortho_fit/exercise.cpp", ""), std::runtime_error);
}

}  // namespace
}  // namespace shadowlab
