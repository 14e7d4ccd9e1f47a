// Headless GL tests on Mesa's llvmpipe: the renderer draws the default scene with shadows where they
// belong, follows the light, leaves no GL objects behind, and reports shader errors as file:line.
#include <algorithm>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>

#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/gl_objects.h"
#include "core/gltf_loader.h"
#include "renderer/renderer.h"
#include "tests/alloc_count.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

struct Pixel {
  int x = -1, y = -1;  // y counted from the bottom (GL order)
};

// Where a world point lands in the last frame, or (-1, -1) when off screen.
Pixel project(const Renderer& r, const glm::vec3& p) {
  const glm::vec4 c = r.camera_projection() * r.camera_view() * glm::vec4(p, 1.0f);
  if (c.w <= 0.0f) return {};
  const glm::vec2 ndc = glm::vec2(c) / c.w;
  const int x = static_cast<int>((ndc.x * 0.5f + 0.5f) * static_cast<float>(r.width()));
  const int y = static_cast<int>((ndc.y * 0.5f + 0.5f) * static_cast<float>(r.height()));
  if (x < 0 || y < 0 || x >= r.width() || y >= r.height()) return {};
  return {x, y};
}

float luminance_at(const Renderer& r, const std::vector<std::uint8_t>& rgba, Pixel p) {
  const int row = r.height() - 1 - p.y;  // read_color is top row first
  const std::size_t i = (static_cast<std::size_t>(row) * static_cast<std::size_t>(r.width()) + static_cast<std::size_t>(p.x)) * 4;
  return (0.2126f * rgba[i] + 0.7152f * rgba[i + 1] + 0.0722f * rgba[i + 2]) / 255.0f;
}

float visibility_at(const Renderer& r, const std::vector<float>& vis, Pixel p) {
  return vis[static_cast<std::size_t>(p.y) * static_cast<std::size_t>(r.width()) + static_cast<std::size_t>(p.x)];
}

class RendererTest : public GlTest {
 protected:
  FrameRequest request(bool gbuffer = true) {
    FrameRequest req;
    req.camera = OrbitCamera::framing(scene.bounds());
    req.width = 640;
    req.height = 360;
    req.gbuffer = gbuffer;
    return req;
  }
  Scene scene = make_default_scene();
  ParamSet params{renderer_param_specs()};
};

TEST_F(RendererTest, ContextIsCoreProfile33OrBetter) {
  const GlInfo info = query_gl_info();
  EXPECT_GE(info.major * 10 + info.minor, 33) << info.version;
  std::printf("GL: %s / %s via %s\n", info.renderer.c_str(), info.version.c_str(), context_->platform().c_str());
}

TEST_F(RendererTest, GroundUnderABoxIsDarkerThanOpenGround) {
  Renderer r;
  r.set_scene(scene);
  params.apply_assignment("light.elevation=90");  // straight down: the box's shadow is right under it
  params.apply_assignment("view.debug_quad=false");
  r.render(params, request());
  const auto rgba = r.read_color();
  // The red box stands on (-2.5, 0, -1.5) with half-size 1; look just beside its base, in front of the
  // camera, at a point the box's shadow covers but the box does not hide: the shadow equals the footprint
  // straight down, so use the open ground instead, and a point under the floating slab (0.84 up).
  const Pixel under_slab = project(r, {-1.8f, 0.0f, 2.4f});
  const Pixel open = project(r, {4.5f, 0.0f, 4.5f});
  ASSERT_GE(under_slab.x, 0);
  ASSERT_GE(open.x, 0);
  const float shadowed = luminance_at(r, rgba, under_slab);
  const float lit = luminance_at(r, rgba, open);
  EXPECT_LT(shadowed, 0.7f * lit) << "shadowed " << shadowed << " lit " << lit;
  const auto vis = r.read_visibility();
  EXPECT_EQ(visibility_at(r, vis, under_slab), 0.0f);
  EXPECT_EQ(visibility_at(r, vis, open), 1.0f);
}

TEST_F(RendererTest, ShadowMovesWithTheLight) {
  Renderer r;
  r.set_scene(scene);
  params.apply_assignment("light.elevation=35");
  // A ground point 1.5 units to the -X side of the red box (half-size 1, 2 tall): with the light toward
  // +X (azimuth 0) the box shadows it; with the light toward -X (azimuth 180) it is in the open.
  const glm::vec3 beside(-4.0f, 0.0f, -1.5f);
  params.apply_assignment("light.azimuth=0");
  r.render(params, request());
  const Pixel p = project(r, beside);
  ASSERT_GE(p.x, 0);
  EXPECT_EQ(visibility_at(r, r.read_visibility(), p), 0.0f);
  params.apply_assignment("light.azimuth=180");
  r.render(params, request());
  EXPECT_EQ(visibility_at(r, r.read_visibility(), p), 1.0f);
}

TEST_F(RendererTest, ShadowPassSkippedWhileTheLightStaysPut) {
  Renderer r;
  r.set_scene(scene);
  FrameRequest req = request(false);
  req.width = 160;
  req.height = 90;
  for (int i = 0; i < 100; ++i) {
    req.camera.yaw_deg += 3.6f;  // the camera orbits once; the light does not move
    r.render(params, req);
  }
  EXPECT_EQ(r.stats().frames, 100);
  EXPECT_EQ(r.stats().shadow_passes, 1);
  params.apply_assignment("light.azimuth=100");
  r.render(params, req);
  EXPECT_EQ(r.stats().shadow_passes, 2);
}

// Cascades follow the camera: their matrices are an input of the map (ShadowPass::frame_inputs), so a
// camera move redraws it, a still camera does not, and a frozen cascade camera (FrameRequest::cascade_camera)
// keeps it while the view moves.
TEST_F(RendererTest, CascadeMapsRedrawWhenTheCameraMovesOnly) {
  Renderer r;
  r.set_scene(scene);
  Features csm;
  csm.technique = ShadowTechnique::CascadedShadowMaps;
  ASSERT_TRUE(r.set_features(csm)) << r.shader_error();
  FrameRequest req = request(false);
  req.width = 160;
  req.height = 90;
  for (int i = 0; i < 5; ++i) r.render(params, req);
  EXPECT_EQ(r.stats().shadow_passes, 1);  // a still camera: drawn once
  for (int i = 0; i < 5; ++i) {
    req.camera.yaw_deg += 3.6f;
    r.render(params, req);
  }
  EXPECT_EQ(r.stats().shadow_passes, 6);  // every move of the camera the cascades follow redraws
  req.cascade_camera = req.camera;
  r.render(params, req);
  const long frozen = r.stats().shadow_passes;
  for (int i = 0; i < 5; ++i) {
    req.camera.yaw_deg += 3.6f;  // the view moves, the cascades' camera does not
    r.render(params, req);
  }
  EXPECT_EQ(r.stats().shadow_passes, frozen);
}

TEST_F(RendererTest, GBufferMatchesTheScene) {
  Renderer r;
  r.set_scene(scene);
  r.render(params, request());
  const GBuffer g = r.read_gbuffer();
  const Bounds b = scene.bounds();
  std::size_t covered = 0;
  for (std::size_t i = 0; i < g.position.size(); ++i) {
    if (!g.covered[i]) continue;
    ++covered;
    for (int a = 0; a < 3; ++a) {
      ASSERT_GE(g.position[i][a], b.min[a] - 1e-3f);
      ASSERT_LE(g.position[i][a], b.max[a] + 1e-3f);
    }
    ASSERT_NEAR(glm::length(g.normal[i]), 1.0f, 1e-3f);
  }
  EXPECT_GT(covered, g.position.size() / 5);  // the ground fills a good part of the frame
  EXPECT_LT(covered, g.position.size());      // and the background shows around it
}

TEST_F(RendererTest, NoGlObjectsAliveAfterShutdown) {
  const int before = live_gl_objects();
  EXPECT_EQ(before, 0);
  {
    Renderer r;
    r.set_scene(scene);
    params.apply_assignment("shadow.map_size=512");
    r.render(params, request());
    params.apply_assignment("shadow.map_size=256");  // reallocation must free the old targets
    r.render(params, request(false));
    EXPECT_GT(live_gl_objects(), 0);
  }
  for (int k = 0; k < static_cast<int>(GlKind::Count); ++k)
    EXPECT_EQ(live_gl_objects(static_cast<GlKind>(k)), 0) << gl_kind_name(static_cast<GlKind>(k));
}

class ShaderErrorTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    dir = fs::temp_directory_path() / ("shadowlab-shader-test-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
  fs::path dir;
};

TEST_F(ShaderErrorTest, CompileErrorNamesFileAndLineAndQuotesIt) {
  write("ok.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  write("helper.glsl", "// helper\nfloat helper() {\n  return 1.0;\n}\n");
  write("broken.frag",
        "#version 330 core\n#include \"helper.glsl\"\nout vec4 o;\nvoid main() {\n  o = vec4(helper()) + undefined_name;\n}\n");
  const ProgramBuild b = build_program({dir / "ok.vert", {}, dir / "broken.frag", {}, {}});
  EXPECT_FALSE(b.program);
  EXPECT_NE(b.error.find("broken.frag:5:"), std::string::npos) << b.error;
  EXPECT_NE(b.error.find("5 | " "  o = vec4(helper()) + undefined_name;"), std::string::npos) << b.error;
}

TEST_F(ShaderErrorTest, ErrorInsideAnIncludeNamesTheIncludedFile) {
  write("ok.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  write("bad_helper.glsl", "// helper\nfloat helper() {\n  return nope;\n}\n");
  write("main.frag", "#version 330 core\n#include \"bad_helper.glsl\"\nout vec4 o;\nvoid main() { o = vec4(helper()); }\n");
  const ProgramBuild b = build_program({dir / "ok.vert", {}, dir / "main.frag", {}, {}});
  EXPECT_NE(b.error.find("bad_helper.glsl:3:"), std::string::npos) << b.error;
  write("missing.frag", "#version 330 core\n#include \"nowhere.glsl\"\nvoid main() {}\n");
  const ProgramBuild m = build_program({dir / "ok.vert", {}, dir / "missing.frag", {}, {}});
  // The column (from 1) is the include's name, its opening quote.
  EXPECT_NE(m.error.find("missing.frag:2:10: error: cannot find include \"nowhere.glsl\""), std::string::npos) << m.error;
}

TEST_F(ShaderErrorTest, DefinesAreInjected) {
  write("ok.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  write("needs_define.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(MY_VALUE); }\n");
  EXPECT_FALSE(build_program({dir / "ok.vert", {}, dir / "needs_define.frag", {}, {}}).program);
  EXPECT_TRUE(build_program({dir / "ok.vert", {}, dir / "needs_define.frag", {{"MY_VALUE", "0.5"}}, {}}).program);
}

TEST_F(ShaderErrorTest, LiveReloadKeepsTheLastGoodProgram) {
  write("ok.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  write("edit.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
  ReloadableProgram p({dir / "ok.vert", {}, dir / "edit.frag", {}, {}});
  ASSERT_TRUE(p.rebuild());
  const GLuint good = p.id();
  EXPECT_FALSE(p.poll_files()) << "nothing changed on disk";
  // A student saves a broken edit: the old program stays, the error is there to show.
  fs::last_write_time(dir / "edit.frag", fs::last_write_time(dir / "edit.frag") - std::chrono::seconds(5));
  write("edit.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0) }\n");
  EXPECT_FALSE(p.poll_files());
  EXPECT_EQ(p.id(), good);
  EXPECT_NE(p.error().find("edit.frag:3:"), std::string::npos) << p.error();
  // Fixed: the new program is swapped in.
  write("edit.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(0.5); }\n");
  fs::last_write_time(dir / "edit.frag", fs::last_write_time(dir / "edit.frag") + std::chrono::seconds(5));
  EXPECT_TRUE(p.poll_files());
  EXPECT_TRUE(p.error().empty());
  EXPECT_EQ(p.generation(), 2);
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// Every real model in assets/models loads and renders headless with shadows on screen.
TEST_F(RendererTest, EveryAssetModelRenders) {
  const std::filesystem::path models = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "assets" / "models";
  ASSERT_TRUE(std::filesystem::is_directory(models)) << models;
  int rendered = 0;
  Renderer r;
  for (const auto& dir : std::filesystem::directory_iterator(models)) {
    if (!dir.is_directory()) continue;  // README.md
    for (const auto& file : std::filesystem::directory_iterator(dir.path())) {
      const auto ext = file.path().extension();
      if (ext != ".gltf" && ext != ".glb") continue;
      SCOPED_TRACE(file.path().string());
      const Scene model = load_gltf(file.path());
      r.set_scene(model);
      FrameRequest req;
      req.camera = OrbitCamera::framing(model.bounds());
      req.width = 320;
      req.height = 180;
      req.gbuffer = true;
      r.render(params, req);
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      const GBuffer g = r.read_gbuffer();
      const auto vis = r.read_visibility();
      std::size_t covered = 0, finite = 0;
      for (std::size_t i = 0; i < g.covered.size(); ++i) {
        covered += g.covered[i];
        finite += std::isfinite(vis[i]) && vis[i] >= 0.0f && vis[i] <= 1.0f;
      }
      EXPECT_GT(covered, g.covered.size() / 20) << "the model fills part of the frame";
      EXPECT_EQ(finite, vis.size()) << "visibility is finite and in [0, 1]";
      ++rendered;
    }
  }
  EXPECT_GE(rendered, 7);  // Box, BoxTextured, CornellBox, Duck (.gltf and .glb), PalmTree, Suzanne
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// Per-pass times are real figures: positive, not under-reported against the wall time around the pass,
// and their sum below the frame's wall time. On llvmpipe the wall time is the figure (its timer queries
// read 0.01 ms for passes that take milliseconds; see timed() in renderer.cpp); on a GPU the query is.
TEST_F(RendererTest, PassTimesArePlausible) {
  Renderer r;
  r.set_scene(scene);
  FrameRequest req = request(false);
  for (int frame = 0; frame < 3; ++frame) {
    params.set("light.azimuth", 30.0 + 20.0 * frame);  // the shadow pass runs every frame
    const auto start = std::chrono::steady_clock::now();
    const FrameStats& stats = r.render(params, req);
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    double sum = 0.0;
    for (const auto& p : stats.passes) {
      EXPECT_GT(p.gpu_ms, 0.0) << p.name;
      EXPECT_LE(p.gpu_ms, p.wall_ms + 1.0) << p.name;
      if (p.wall_clock) {
        EXPECT_EQ(p.gpu_ms, p.wall_ms) << p.name;
      }
      sum += p.gpu_ms;
    }
    EXPECT_LE(sum, wall + 1.0) << "frame " << frame;
    // A frame whose shadow pass is skipped still reports a lit pass of real cost (llvmpipe's query read
    // 0.01 ms there against 4-6 ms of wall time).
    for (const auto& p : stats.passes) EXPECT_GE(p.gpu_ms, 0.25 * p.wall_ms) << p.name;
  }
  params.set("view.debug_quad", 0.0);
  const FrameStats& still = r.render(params, req);  // same light: no shadow pass
  ASSERT_EQ(still.passes.size(), 1u);
  EXPECT_EQ(still.passes[0].name, "lit");
  EXPECT_GE(still.passes[0].gpu_ms, 0.25 * still.passes[0].wall_ms);
  const std::string gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (gl_renderer.find("llvmpipe") != std::string::npos) {
    EXPECT_TRUE(still.passes[0].wall_clock);
    EXPECT_GT(still.passes[0].gpu_ms, 0.2) << "a 640x360 lit pass on llvmpipe takes milliseconds";
  }
}

// The interactive frame waits for nothing: under the window's timing modes no glFinish and no
// blocking query read, with the light moving (shadow pass and its sample count) and still; the ring's
// times and sample counts come back a few frames later. Exact timing (the benchmark's) counts its waits,
// so the counters are seen to count.
TEST_F(RendererTest, InteractiveTimingWaitsForNothing) {
  EXPECT_EQ(interactive_timing(true, true), TimingMode::Queries);
  EXPECT_EQ(interactive_timing(true, false), TimingMode::Queries);
  EXPECT_EQ(interactive_timing(false, true), TimingMode::Exact);
  EXPECT_EQ(interactive_timing(false, false), TimingMode::Off);
  for (TimingMode mode : {TimingMode::Queries, TimingMode::Off}) {
    Renderer r;
    r.set_scene(scene);
    r.set_timing(mode);
    const FrameRequest req = request(false);
    for (int frame = 0; frame < 12; ++frame) {
      // Moving, then still, then one move in the last frame: its sample count is the one the next
      // frame must publish (the earlier ones may already have been published by the still frames).
      params.set("light.azimuth", frame < 6 || frame == 11 ? 30.0 + 10.0 * frame : 90.0);
      const FrameStats& stats = r.render(params, req);
      ASSERT_FALSE(stats.passes.empty());
      for (const auto& p : stats.passes) EXPECT_FALSE(p.timed) << p.name;
    }
    glFinish();  // the test's own wait, after the frames: the ring's results are all available now
    const FrameStats& last = r.render(params, req);
    EXPECT_EQ(last.gl_finishes, 0) << static_cast<int>(mode);
    EXPECT_EQ(last.blocking_query_reads, 0) << static_cast<int>(mode);
    EXPECT_GT(last.shadow_passes, 1);
    EXPECT_GT(last.shadow_texels_written, 0) << "sample counts come back through the ring";
    if (mode == TimingMode::Queries) {
      ASSERT_FALSE(last.timed_passes.empty());
      EXPECT_GE(last.timed_frames_ago, 1);
      EXPECT_TRUE(std::any_of(last.timed_passes.begin(), last.timed_passes.end(), [](const PassTiming& p) { return p.name == "lit"; }));
    }
  }
  Renderer exact;  // the default: every pass bracketed by glFinish, its query read at once
  exact.set_scene(scene);
  const FrameStats& stats = exact.render(params, request(false));
  EXPECT_EQ(stats.gl_finishes, 2 * static_cast<long>(stats.passes.size()));
  EXPECT_GE(stats.blocking_query_reads, static_cast<long>(stats.passes.size()));
}

// A still frame allocates nothing on the C++ heap: every lab's frame as the window draws it (debug quad
// hidden, light and camera still, timing off or in the query ring), once the first frames have built
// what they need (programs, targets, the map). A frame whose light moves is seen to be counted.
TEST_F(RendererTest, StillFramesAllocateNothing) {
  FrameRequest req = request(false);
  for (const Lab& lab : all_labs()) {
    Renderer r;
    r.set_scene(scene);
    ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
    ParamSet p = lab_params(lab);
    p.set("view.debug_quad", 0.0);
    for (TimingMode mode : {TimingMode::Off, TimingMode::Queries}) {
      r.set_timing(mode);
      for (int f = 0; f < 6; ++f) r.render(p, req);  // warm-up; the query ring fills
      const long before = test::allocations();
      for (int f = 0; f < 10; ++f) r.render(p, req);
      EXPECT_EQ(test::allocations() - before, 0) << "lab " << lab.number << ", timing " << static_cast<int>(mode);
    }
  }
  // The counter counts: a frame after set_features (new programs are built) allocates.
  Renderer r;
  r.set_scene(scene);
  r.render(params, req);
  const long before = test::allocations();
  ASSERT_TRUE(r.set_features({}));
  r.render(params, req);
  EXPECT_GT(test::allocations() - before, 0);
}

// Lab 11's billboards look their uniforms up by name once per program (BillboardPass's UniformCache):
// a still frame with the shadow quads shown looks up none; after a live reload of the shadow pass's
// file (a new program, whose locations may differ) the next frame looks them up again, once, and draws
// the same picture.
TEST_F(RendererTest, BillboardUniformsAreLookedUpOncePerProgram) {
  const Lab* lab = find_lab(11);
  ASSERT_NE(lab, nullptr);
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-uniforms-" + std::to_string(std::random_device{}()));
  fs::create_directories(dir);
  const fs::path quad = dir / "shadow_quad.glsl";
  fs::copy_file(data_dir() / lab->solution_files.at(0), quad);
  Features hooks = lab->hooks(Impl::Solution);
  hooks.includes["lab/billboard.glsl"] = quad.string();
  Renderer r;
  r.set_scene(scene);
  ASSERT_TRUE(r.set_features(hooks)) << r.shader_error();
  ParamSet p = lab_params(*lab);
  p.set("view.debug_quad", 0.0);
  p.apply_assignment("billboard.show_shadow_quads=1");
  const FrameRequest req = request(false);
  for (int f = 0; f < 3; ++f) r.render(p, req);
  const auto picture = r.read_color();
  auto lookups_per_frame = [&](int frames) {
    const long before = Uniform::lookups();
    for (int f = 0; f < frames; ++f) r.render(p, req);
    return static_cast<double>(Uniform::lookups() - before) / frames;
  };
  const double still = lookups_per_frame(10);
  // The shadow pass's file is saved again (a comment added): the renderer swaps in a new program.
  { std::ofstream(quad, std::ios::app) << "\n// saved again\n"; }
  fs::last_write_time(quad, fs::last_write_time(quad) + std::chrono::seconds(2));
  ASSERT_TRUE(r.poll_shader_files());
  const double reload = lookups_per_frame(1);
  EXPECT_EQ(r.read_color(), picture);
  const double after = lookups_per_frame(10);
  std::printf("uniform lookups per frame (lab 11, shadow quads shown): still %.1f, the frame after a reload %.1f, "
              "then %.1f\n", still, reload, after);
  EXPECT_EQ(still, 0.0);
  EXPECT_GE(reload, 5.0);  // the shadow program's five, at least (the others' too: every program was polled)
  EXPECT_EQ(after, 0.0);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// The shadow map's picture is the map itself, top row first (PNG order): white exactly where nothing
// was drawn (depth 1), for the depth map and for the moments' depth buffer alike.
TEST_F(RendererTest, ShadowMapImageIsTheMapTopRowFirst) {
  for (ShadowTechnique technique : {ShadowTechnique::Depth, ShadowTechnique::Moments}) {
    Renderer r;
    r.set_scene(scene);
    Features hooks;
    hooks.technique = technique;
    ASSERT_TRUE(r.set_features(hooks)) << r.shader_error();
    params.apply_assignment("shadow.map_size=256");
    params.apply_assignment("light.elevation=30");  // the ground's far corners stay empty in the map
    r.render(params, request(false));
    int n = 0, image_n = 0;
    const std::vector<float> depth = r.read_shadow_depth(&n);
    const std::vector<std::uint8_t> image = r.shadow_map_image(&image_n);
    ASSERT_EQ(image_n, n);
    ASSERT_EQ(image.size(), depth.size() * 4);
    long background = 0, mismatches = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const bool empty = depth[static_cast<std::size_t>(y) * n + x] >= 1.0f;
        const std::uint8_t grey = image[(static_cast<std::size_t>(n - 1 - y) * n + x) * 4];
        background += empty;
        mismatches += empty != (grey == 255);
      }
    EXPECT_GT(background, 0);
    EXPECT_LT(background, static_cast<long>(n) * n);
    EXPECT_EQ(mismatches, 0) << (technique == ShadowTechnique::Depth ? "depth map" : "moments' depth");
  }
}

}  // namespace
}  // namespace shadowlab
