// Headless GL tests of the figures `shadowlab bench` reports beside its sweep (app/bench_figures.h):
// every technique runs exactly its passes, and the oracle's cost counts the rays each band casts. The
// timings themselves are the benchmark's output, not asserted here.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "app/bench_figures.h"
#include "renderer/renderer.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class BenchFiguresTest : public GlTest {
 protected:
  Scene scene = make_default_scene();
};

TEST_F(BenchFiguresTest, EveryTechniqueRunsItsPassesAndNoOthers) {
  Renderer r;
  r.set_scene(scene);
  const std::vector<TechniquePasses> rows = measure_technique_passes(r, 256, 160, 90, 2);
  using Names = std::set<std::string>;
  const Names map{"shadow", "lit"}, cube{"cube_shadow", "lit"}, volumes{"ambient", "volumes", "lit"};
  const std::map<std::string, Names> expected = {
      {"directional 1 tap", map},
      {"pcf 3x3", map},
      {"pcf 9x9", map},
      {"pcf hw 3x3", map},
      {"spot", map},
      {"point 6 passes", cube},
      {"point 1 pass (GS)", cube},
      {"moments", {"moments", "lit"}},
      {"moments, fast blur r4", {"moments", "blur_x", "blur_y", "lit"}},
      {"volumes z-fail", volumes},
      {"volumes z-pass", volumes},
      {"volumes z-fail, point", volumes},
      {"normals view", {"shadow", "lit", "normals_view"}},
      {"volumes wireframe", {"ambient", "volumes", "lit", "volumes_view"}},
  };
  ASSERT_EQ(rows.size(), expected.size());
  for (const auto& row : rows) {
    SCOPED_TRACE(row.name);
    ASSERT_TRUE(expected.count(row.name));
    Names names;
    double sum = 0.0;
    for (const auto& [name, ms] : row.pass_ms) {
      names.insert(name);
      EXPECT_GT(ms, 0.0) << name;
      sum += ms;
    }
    EXPECT_EQ(names, expected.at(row.name));
    EXPECT_DOUBLE_EQ(row.total_ms, sum);
  }
}

TEST_F(BenchFiguresTest, OracleCostCountsTheRaysOfEachBand) {
  Renderer r;
  r.set_scene(scene);
  ParamSet params(renderer_param_specs());
  FrameRequest request;
  request.camera = OrbitCamera::framing(scene.bounds());
  request.width = 160;
  request.height = 90;
  request.gbuffer = true;
  r.render(params, request);
  const GBuffer g = r.read_gbuffer();
  OracleLight sun;
  sun.to_light = r.to_light();
  sun.image_x = r.light_view().image_x;
  sun.image_y = r.light_view().image_y;
  sun.texel_world_size = 0.02f;
  OracleLight spot;
  spot.positional = true;
  spot.position = {-4.0f, 9.0f, 3.0f};
  spot.texel_angle = 1.2f / 2048.0f;
  const OracleCost cost = measure_oracle_cost(scene, g, sun, spot, 1);
  EXPECT_GT(cost.build_ms, 0.0);
  EXPECT_GT(cost.triangles, 0u);
  ASSERT_EQ(cost.runs.size(), 4u);
  const std::uint64_t covered = static_cast<std::uint64_t>(std::count(g.covered.begin(), g.covered.end(), 1));
  // One ray per lit-facing pixel without a band or with a screen band; up to 8 more per pixel with one.
  for (const auto& run : cost.runs) {
    EXPECT_GT(run.ms, 0.0) << run.what;
    EXPECT_GT(run.rays, 0u) << run.what;
    EXPECT_LE(run.rays, 9 * covered) << run.what;
    EXPECT_GT(run.mrays_per_s(), 0.0) << run.what;
  }
  EXPECT_EQ(cost.runs[1].rays, cost.runs[2].rays) << "a screen band casts no extra ray";
  EXPECT_GT(cost.runs[0].rays, cost.runs[2].rays) << "the band's samples are rays too";
  EXPECT_EQ(cost.runs[2].edge_pixels, 0) << "no band: every valid pixel is interior";
}

}  // namespace
}  // namespace shadowlab
