// The benchmark's results as plots: the front each scene's points give, the errors a bad bench.json
// gives, and the plot drawn through a bare ImGui context (no window, no GL) with its labels apart.
#include <gtest/gtest.h>

#ifndef _WIN32
#include <sys/stat.h>  // mkfifo
#endif

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/bench_plot.h"
#include "tests/imgui_fixture.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

nlohmann::json point(const std::string& scene, const std::string& technique, int map_size, double ms, double error,
                     const std::string& family = "hard (lab 1)") {
  return {{"scene", scene}, {"technique", technique}, {"family", family}, {"map_size", map_size},
          {"gpu_ms", ms},   {"error", error}};
}

TEST(BenchPlots, FrontPerSceneLabelsAndGroups) {
  const nlohmann::json report = {
      {"points",
       {point("a", "hard", 512, 5, 0.003), point("a", "hard", 1024, 10, 0.001), point("a", "pcf 3x3", 1024, 12, 0.002, "PCF"),
        point("a", "volumes", 0, 4, 0.004, "volumes"), point("b", "hard", 512, 1, 0.5), point("b", "pcf 3x3", 512, 1, 0.4, "PCF")}}};
  const BenchPlots plots = bench_plots_from_json(report);
  ASSERT_EQ(plots.by_scene.size(), 2u);
  EXPECT_EQ(plots.families, (std::vector<std::string>{"hard (lab 1)", "PCF", "volumes"}));
  const auto& a = plots.by_scene.at("a");
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].label, "hard 512");
  EXPECT_EQ(a[3].label, "volumes");  // no map: no size in the label
  EXPECT_EQ(a[2].group, 1);
  // hard 1024 (10 ms, 0.001) beats pcf 3x3 1024 (12 ms, 0.002); the other three are on the front.
  EXPECT_TRUE(a[0].pareto);
  EXPECT_TRUE(a[1].pareto);
  EXPECT_FALSE(a[2].pareto);
  EXPECT_TRUE(a[3].pareto);
  // Equal time, lower error wins; fronts are per scene.
  EXPECT_FALSE(plots.by_scene.at("b")[0].pareto);
  EXPECT_TRUE(plots.by_scene.at("b")[1].pareto);
}

// The same frames graded against suns with a size: a plot per scene and size, with a front of its own
// (here the blurred map, slower, joins it where the penumbra is wide), and the point-light plot unchanged.
TEST(BenchPlots, EachLightSizeHasItsOwnPlotAndFront) {
  nlohmann::json hard = point("a", "hard", 1024, 5, 0.001), blurred = point("a", "vsm r4", 1024, 9, 0.004, "VSM");
  hard["light_sizes"] = {{{"sun_deg", 1.0}, {"error", 0.002}}, {{"sun_deg", 5.0}, {"error", 0.02}}};
  blurred["light_sizes"] = {{{"sun_deg", 1.0}, {"error", 0.005}}, {{"sun_deg", 5.0}, {"error", 0.01}, {"gpu_ms", 11}}};
  const BenchPlots plots = bench_plots_from_json({{"points", {hard, blurred}}});
  ASSERT_EQ(plots.by_scene.size(), 3u);
  EXPECT_EQ(sized_light_plot("a", 5.0), "a, sun 5 deg");
  EXPECT_TRUE(is_sized_light_plot("a, sun 5 deg"));
  EXPECT_FALSE(is_sized_light_plot("a"));
  const auto& point_sun = plots.by_scene.at("a");
  EXPECT_TRUE(point_sun[0].pareto);
  EXPECT_FALSE(point_sun[1].pareto);
  EXPECT_FALSE(plots.by_scene.at("a, sun 1 deg")[1].pareto);
  const auto& wide = plots.by_scene.at("a, sun 5 deg");
  ASSERT_EQ(wide.size(), 2u);
  EXPECT_DOUBLE_EQ(wide[0].error, 0.02);
  EXPECT_EQ(wide[1].label, "vsm r4 1024");
  EXPECT_DOUBLE_EQ(wide[1].time_ms, 11.0);  // timed again at that size
  EXPECT_DOUBLE_EQ(plots.by_scene.at("a, sun 1 deg")[1].time_ms, 9.0);
  EXPECT_TRUE(wide[0].pareto);
  EXPECT_TRUE(wide[1].pareto);
  nlohmann::json bad = hard;
  bad["light_sizes"] = {{{"sun_deg", 1.0}}};
  try {
    bench_plots_from_json({{"points", {bad}}});
    FAIL() << "a light size without its error was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("point 0 has no \"error\""), std::string::npos) << e.what();
  }
  bad["light_sizes"] = 3;
  EXPECT_THROW(bench_plots_from_json({{"points", {bad}}}), std::runtime_error);
}

TEST(BenchPlots, MissingOrWrongFieldsNameThePoint) {
  nlohmann::json bad = point("a", "hard", 512, 5, 0.003);
  bad.erase("error");
  try {
    bench_plots_from_json({{"points", {point("a", "hard", 512, 5, 0.003), bad}}});
    FAIL() << "accepted a point without an error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "point 1 has no \"error\"");
  }
  nlohmann::json text_time = point("a", "hard", 512, 5, 0.003);
  text_time["gpu_ms"] = "fast";
  EXPECT_THROW(bench_plots_from_json({{"points", {text_time}}}), std::runtime_error);
  EXPECT_THROW(bench_plots_from_json(nlohmann::json::array()), std::runtime_error);
}

class BenchFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("shadowlab_bench_plot_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  std::string error_of(const fs::path& file) {
    try {
      load_bench_plots(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir;
};

TEST_F(BenchFiles, ErrorsNameTheFileAndTheProblem) {
  const fs::path missing = dir / "none.json";
  EXPECT_EQ(error_of(missing), missing.string() + ": cannot open the file: No such file or directory");
  // Issue 18: a FIFO made --bench wait forever; refused unopened. Nesting is bounded before parsing.
#ifndef _WIN32  // no FIFOs on native Windows
  const fs::path fifo = dir / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of(fifo), fifo.string() + ": cannot open the file: is a FIFO, not a regular file");
#endif
  const fs::path deep = write("deep.json", "{\"points\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}");
  EXPECT_NE(error_of(deep).find("deep.json: not valid JSON (the JSON nests arrays and objects deeper than 64 levels)"),
            std::string::npos)
      << error_of(deep);
  const fs::path broken = write("broken.json", "{\"points\": [");
  EXPECT_EQ(error_of(broken).rfind(broken.string() + ": not valid JSON", 0), 0u) << error_of(broken);
  const fs::path other = write("other.json", "{\"labs\": []}");
  EXPECT_EQ(error_of(other), other.string() + ": no \"points\" array (is this a shadowlab bench.json?)");
  const fs::path empty = write("empty.json", "{\"points\": []}");
  EXPECT_EQ(error_of(empty), empty.string() + ": no points to plot");
  const nlohmann::json good = {{"points", {point("a", "hard", 512, 5, 0.003)}}};
  const BenchPlots plots = load_bench_plots(write("good.json", good.dump()));
  EXPECT_TRUE(plots.by_scene.at("a").front().pareto);
}

// The project's own measured results (docs/bench.json, shown by the window and the README) load and
// have a front in each of the benchmark's five scenes.
TEST(BenchPlots, ShippedResultsLoad) {
  const BenchPlots plots = load_bench_plots(fs::path(SHADOWLAB_SOURCE_DIR) / "docs" / "bench.json");
  for (const char* scene : {"default", "grazing", "stacked", "palmtree", "palmtree-island"}) {
    ASSERT_TRUE(plots.by_scene.contains(scene)) << scene;
    const auto& points = plots.by_scene.at(scene);
    EXPECT_GE(points.size(), 20u) << scene;
    EXPECT_TRUE(std::any_of(points.begin(), points.end(), [](const PlotPoint& p) { return p.pareto; })) << scene;
  }
}

// Labels of nearby front points go to different corners, none overlapping; near the plot's right edge
// they move left of the point.
TEST(PlotLabels, ApartAndInside) {
  const ImVec2 size(80, 14);
  const std::vector<ImVec2> anchors = {{100, 100}, {104, 102}, {108, 98}, {590, 300}};
  const auto at = place_labels(anchors, std::vector<ImVec2>(anchors.size(), size), ImVec2(0, 0), ImVec2(600, 400));
  ASSERT_EQ(at.size(), anchors.size());
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i + 1; j < 3; ++j) {
      const bool overlap = at[i].x < at[j].x + size.x && at[j].x < at[i].x + size.x && at[i].y < at[j].y + size.y &&
                           at[j].y < at[i].y + size.y;
      EXPECT_FALSE(overlap) << i << " and " << j;
    }
  EXPECT_EQ(at[0].x, 108.0f);                // the first takes the default corner, above right
  EXPECT_LE(at[3].x + size.x, 600.0f);       // the last would leave the plot on the right: left of it
  EXPECT_LT(at[3].x, anchors[3].x);
}

// A crowded front (nine points within a few pixels, as the island scene's cascades are): every label
// finds a place of its own inside the plot, stacked above and below once the four corners are taken.
TEST(PlotLabels, CrowdedFrontStaysApart) {
  const ImVec2 size(90, 14);
  std::vector<ImVec2> anchors;
  for (int i = 0; i < 9; ++i) anchors.push_back({300.0f + 3.0f * static_cast<float>(i), 200.0f + (i % 2 ? 1.0f : -1.0f)});
  const auto at = place_labels(anchors, std::vector<ImVec2>(anchors.size(), size), ImVec2(0, 0), ImVec2(600, 400));
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_GE(at[i].y, 0.0f);
    EXPECT_LE(at[i].y + size.y, 400.0f);
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      const bool overlap = at[i].x < at[j].x + size.x && at[j].x < at[i].x + size.x && at[i].y < at[j].y + size.y &&
                           at[j].y < at[i].y + size.y;
      EXPECT_FALSE(overlap) << i << " and " << j;
    }
  }
}

// What the Speed against error window builds, through a bare ImGui context (no window, no GL).
using PlotDrawing = BareImGuiTest;

TEST_F(PlotDrawing, WindowDrawsThePlotOnlyWhenOpen) {
  const nlohmann::json three = {{"points", {point("a", "hard", 512, 5, 0.003), point("a", "hard", 1024, 10, 0.001),
                                            point("a", "pcf", 1024, 12, 0.002)}}};
  nlohmann::json six = three;
  for (const auto& p : {point("a", "vsm", 512, 3, 0.01), point("a", "vsm", 1024, 30, 0.02), point("a", "pcf", 512, 40, 0.03)})
    six["points"].push_back(p);
  const BenchPlots small = bench_plots_from_json(three), larger = bench_plots_from_json(six);
  BenchPanelState state;
  state.path = "bench.json";
  auto vertices = [&](const BenchPlots* plots) {  // a frame's vertex count, the second of two (layout settled)
    for (int i = 0; i < 2; ++i) {
      ImGui::NewFrame();
      draw_bench_window(plots, state, true);
      ImGui::Render();
    }
    return ImGui::GetDrawData()->TotalVtxCount;
  };
  EXPECT_EQ(vertices(&small), 0);  // closed: nothing is built
  state.open = true;
  const int none = vertices(nullptr), with_three = vertices(&small), with_six = vertices(&larger);
  EXPECT_EQ(state.scene, "a");
  // Nothing loaded: a hint, no plot. Loaded: the plot, and every point drawn (more points, more vertices).
  EXPECT_GT(with_three, none + 300) << none;
  EXPECT_GT(with_six, with_three + 3 * 20) << with_three;
}

}  // namespace
}  // namespace shadowlab
