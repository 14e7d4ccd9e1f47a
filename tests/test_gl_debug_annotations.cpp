// The words the renderer records while it draws (renderer/debug_annotations.h): every debug quad of
// every lab's solution, in every channel of view.debug_channel, carries a label saying what it shows,
// inside the frame; PCSS's debug view records its legend, and only while it is on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <vector>

#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/renderer.h"
#include "core/scene.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class DebugAnnotationsGlTest : public GlTest {};

// A 160x90 frame with the camera framed on the renderer's scene: enough for a legend to be recorded.
FrameRequest small_framed_request(const Renderer& r, const ParamSet& p) {
  FrameRequest request;
  request.width = 160;
  request.height = 90;
  request.camera = frame_scene_camera(r.scene(), p);
  return request;
}

TEST_F(DebugAnnotationsGlTest, EveryLabsDebugQuadHasALabel) {
  const Scene scene = make_default_scene();
  FrameRequest request;
  request.width = 256;
  request.height = 144;
  for (const Lab& lab : all_labs()) {
    Renderer r;
    r.set_scene(scene);
    ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
    ParamSet p = lab_params(lab);
    request.camera = frame_scene_camera(r.scene(), p);
    p.set("view.debug_quad", 0.0);
    r.render(p, request);
    EXPECT_TRUE(r.annotations().quads.empty()) << "lab " << lab.number << ": labels without quads";
    const std::vector<std::uint8_t> without = r.read_color();
    for (const char* channel : {"all", "depth", "moment 1", "moment 2", "variance"}) {
      p.set("view.debug_quad", 1.0);
      p.set_from_string("view.debug_channel", channel);
      r.render(p, request);
      const auto& quads = r.annotations().quads;
      const std::string where = "lab " + std::to_string(lab.number) + ", channel " + channel;
      std::set<std::string> texts;
      for (const DebugQuadLabel& q : quads) {
        EXPECT_FALSE(q.text.empty()) << where;
        texts.insert(q.text);
        EXPECT_GE(q.x, 0) << where << ": " << q.text;
        EXPECT_GE(q.y, 0) << where << ": " << q.text;
        EXPECT_LE(q.x + q.width, request.width) << where << ": " << q.text;
        EXPECT_LE(q.y + q.height, request.height) << where << ": " << q.text;
      }
      EXPECT_EQ(texts.size(), quads.size()) << where << ": two quads say the same";
      // Whatever the quads changed in the frame lies inside a labelled quad: no quad is drawn unlabelled.
      const std::vector<std::uint8_t> with = r.read_color();
      ASSERT_EQ(with.size(), without.size());
      long changed = 0, unlabelled = 0;
      for (int row = 0; row < request.height; ++row)
        for (int x = 0; x < request.width; ++x) {
          const std::size_t i = (static_cast<std::size_t>(row) * request.width + x) * 4;
          if (std::equal(&with[i], &with[i] + 3, &without[i])) continue;
          ++changed;
          const int y = request.height - 1 - row;  // GL's row, as the labels' rectangles count
          const bool inside = std::any_of(quads.begin(), quads.end(), [&](const DebugQuadLabel& q) {
            return x >= q.x && x < q.x + q.width && y >= q.y && y < q.y + q.height;
          });
          if (!inside) ++unlabelled;
        }
      EXPECT_EQ(unlabelled, 0) << where << ": pixels drawn by a quad without a label";
      if (r.shadow_pass()->shape().has_map && !quads.empty()) {
        EXPECT_GT(changed, 0) << where;
      }
    }
  }
}

TEST_F(DebugAnnotationsGlTest, PcssViewRecordsItsLegend) {
  const Lab& lab = *find_lab(16);
  Renderer r;
  r.set_scene(make_default_scene());
  ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
  ParamSet p = lab_params(lab);
  const FrameRequest request = small_framed_request(r, p);
  r.render(p, request);
  EXPECT_TRUE(r.annotations().legends.empty()) << "a legend with the debug view off";
  p.set_from_string("pcss.view", "kernel width");
  r.render(p, request);
  ASSERT_EQ(r.annotations().legends.size(), 1u);
  EXPECT_EQ(r.annotations().legends[0].title, "PCSS kernel width");
  p.set_from_string("pcss.view", "blocker distance");
  r.render(p, request);
  ASSERT_EQ(r.annotations().legends.size(), 1u);
  EXPECT_EQ(r.annotations().legends[0].title, "PCSS blocker distance");
}

// The overlays' legends: lab 12's cascade view names each cascade's tint, lab 4's remap view its ramp; their
// programs build with the colours given as defines.
TEST_F(DebugAnnotationsGlTest, OverlayViewsRecordTheirLegends) {
  struct Case {
    int lab;
    const char* key;
    const char* title;
  };
  for (const Case& c : {Case{12, "csm.show_cascades", "Cascades"}, Case{4, "vsm.show_remap", "Light-bleeding remap"}}) {
    const Lab& lab = *find_lab(c.lab);
    Renderer r;
    r.set_scene(make_default_scene());
    ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
    ParamSet p = lab_params(lab);
    const FrameRequest request = small_framed_request(r, p);
    p.set(c.key, 0.0);
    r.render(p, request);
    EXPECT_TRUE(r.annotations().legends.empty()) << c.key;
    p.set(c.key, 1.0);
    r.render(p, request);
    EXPECT_TRUE(r.shader_error().empty()) << r.shader_error();
    ASSERT_EQ(r.annotations().legends.size(), 1u) << c.key;
    EXPECT_EQ(r.annotations().legends[0].title, c.title);
    if (c.lab == 12) {
      EXPECT_EQ(static_cast<double>(r.annotations().legends[0].swatches.size()), p.get("csm.count"));
    }
  }
}

}  // namespace
}  // namespace shadowlab
