#include "app/bench_figures.h"

#include <algorithm>
#include <cmath>

#include <chrono>

#include "renderer/moments_pass.h"
#include "core/technique_params.h"
#include "core/vsm_params.h"

namespace shadowlab {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

namespace {

double pass_ms(const FrameStats& stats, const char* name) {
  for (const auto& p : stats.passes)
    if (p.name == name) return p.gpu_ms;
  return 0.0;
}

}  // namespace

std::vector<BlurTiming> measure_blur_methods(Renderer& renderer, const ParamSet& params, const std::vector<int>& radii,
                                             int frames) {
  ParamSet p = params;
  for (const auto& spec : vsm_param_specs())
    if (!p.find(spec.key)) p.declare(spec);
  if (p.find("view.debug_quad")) p.set("view.debug_quad", 0.0);
  if (p.find("vsm.show_remap")) p.set("vsm.show_remap", 0.0);
  const BlurMethod methods[] = {BlurMethod::Separable, BlurMethod::Fast, BlurMethod::Brute2D};
  constexpr int kMethods = 3;

  // A small view: the lit pass runs every frame but is not what is measured.
  FrameRequest request;
  request.camera = OrbitCamera::framing(renderer.scene().bounds());
  request.width = 64;
  request.height = 64;

  std::vector<BlurTiming> out;
  for (int radius : radii) {
    if (radius <= 0) continue;
    const double sigma = std::max(0.5 * radius, p.find("vsm.blur_sigma")->min);
    p.set("vsm.blur_radius", radius);
    p.set("vsm.blur_sigma", sigma);
    auto render = [&](BlurMethod method) -> const FrameStats& {
      p.set("vsm.blur_method", static_cast<double>(static_cast<int>(method)));
      renderer.invalidate_shadow_map();
      return renderer.render(p, request);
    };
    for (BlurMethod m : methods) render(m);  // warm-up: programs compiled, targets allocated

    std::vector<double> x[kMethods], y[kMethods], total[kMethods];
    for (int f = 0; f < std::max(frames, 1); ++f)
      for (int k = 0; k < kMethods; ++k) {
        const FrameStats& s = render(methods[k]);
        const bool brute = methods[k] == BlurMethod::Brute2D;
        const double mx = pass_ms(s, brute ? "blur_2d" : "blur_x"), my = brute ? 0.0 : pass_ms(s, "blur_y");
        x[k].push_back(mx);
        y[k].push_back(my);
        total[k].push_back(mx + my);
      }

    std::vector<float> reference;
    int size = 0;
    for (int k = 0; k < kMethods; ++k) {
      render(methods[k]);
      const std::vector<float> moments = renderer.read_moments(&size);
      if (k == 0) reference = moments;
      BlurTiming t;
      t.method = blur_method_name(methods[k]);
      t.radius = radius;
      t.sigma = sigma;
      t.map_size = size;
      t.format = p.get(param::vsm_format);
      t.ms_x = median(x[k]);
      t.ms_y = median(y[k]);
      t.ms_total = median(total[k]);
      for (std::size_t i = 0; i < moments.size(); ++i) {
        if (!std::isfinite(moments[i])) {
          ++t.non_finite;
          continue;
        }
        t.max_abs_diff_vs_separable = std::max(
            t.max_abs_diff_vs_separable, std::abs(static_cast<double>(moments[i]) - static_cast<double>(reference[i])));
      }
      out.push_back(t);
    }
  }
  renderer.invalidate_shadow_map();
  return out;
}

namespace {

struct TechniqueCase {
  const char* name;
  Features features;
  std::vector<const char*> assignments;
};

std::vector<TechniqueCase> technique_cases() {
  Features pcf, spot, point, moments, volumes;
  pcf.shadow_test = "pcf";  // shaders/shadow/pcf.glsl
  spot.light = LightType::Spot;
  point.light = LightType::Point;
  moments.technique = ShadowTechnique::Moments;
  volumes.technique = ShadowTechnique::ShadowVolumes;
  return {
      {"directional 1 tap", {}, {}},
      {"pcf 3x3", pcf, {"pcf.kernel=3"}},
      {"pcf 9x9", pcf, {"pcf.kernel=9"}},
      {"pcf hw 3x3", pcf, {"pcf.kernel=3", "pcf.hardware=true"}},
      {"spot", spot, {"light.position_x=5", "light.position_y=7", "light.position_z=4", "light.cone_deg=40"}},
      {"point 6 passes", point, {}},
      {"point 1 pass (GS)", point, {"point.single_pass=true"}},
      {"moments", moments, {}},
      {"moments, fast blur r4", moments, {"vsm.blur_radius=4", "vsm.blur_sigma=2", "vsm.blur_method=fast"}},
      {"volumes z-fail", volumes, {}},
      {"volumes z-pass", volumes, {"volume.method=z-pass"}},
      {"volumes z-fail, point", volumes, {"light.type=point"}},
      {"normals view", {}, {"view.normals=true"}},
      {"volumes wireframe", volumes, {"view.volumes=true"}},
  };
}

// Every parameter group, so that each case can set what it needs.
ParamSet every_parameter() {
  ParamSet p(renderer_param_specs());
  for (auto group : {vsm_param_specs(), light_param_specs(), pcf_param_specs(), point_param_specs(), volume_param_specs()})
    for (auto& spec : group) p.declare(std::move(spec));
  p.set("view.debug_quad", 0.0);
  return p;
}

}  // namespace

std::vector<TechniquePasses> measure_technique_passes(Renderer& renderer, int map_size, int width, int height,
                                                      int frames) {
  FrameRequest request;
  request.camera = OrbitCamera::framing(renderer.scene().bounds());
  request.width = width;
  request.height = height;
  std::vector<TechniquePasses> out;
  for (const TechniqueCase& c : technique_cases()) {
    ParamSet params = every_parameter();
    params.set_from_string("shadow.map_size", std::to_string(map_size));
    for (const char* a : c.assignments) params.apply_assignment(a);
    if (!renderer.set_features(c.features)) throw std::runtime_error(renderer.shader_error());
    renderer.render(params, request);  // warm-up: shaders compile during the first frame
    std::map<std::string, std::vector<double>> ms;
    for (int frame = 0; frame < std::max(frames, 1); ++frame) {
      renderer.invalidate_shadow_map();
      for (const auto& pass : renderer.render(params, request).passes) ms[std::string(pass.name)].push_back(pass.gpu_ms);
    }
    TechniquePasses row{c.name, {}, 0.0};
    for (auto& [name, v] : ms) {
      row.pass_ms[name] = median(v);
      row.total_ms += row.pass_ms[name];
    }
    out.push_back(std::move(row));
  }
  renderer.invalidate_shadow_map();
  return out;
}

OracleCost measure_oracle_cost(const Scene& scene, const GBuffer& gbuffer, const OracleLight& directional,
                               const OracleLight& positional, int repeats) {
  repeats = std::max(repeats, 1);
  OracleCost cost;
  std::vector<double> build_ms;
  for (int k = 0; k < repeats; ++k) build_ms.push_back(1e3 * Oracle(scene).build_seconds());
  cost.build_ms = median(build_ms);
  const Oracle oracle(scene);
  cost.triangles = oracle.triangle_count();
  BandSpec screen, none;
  screen.fixed_screen_pixels = 3;
  none.samples = 0;
  const struct {
    const char* what;
    const OracleLight& light;
    BandSpec band;
  } runs[] = {{"directional, band 8 samples", directional, BandSpec{}},
              {"directional, screen band 3 px", directional, screen},
              {"directional, no band", directional, none},
              {"positional, band 8 samples", positional, BandSpec{}}};
  for (const auto& run : runs) {
    (void)oracle.evaluate(gbuffer, run.light, run.band);  // warm-up
    std::vector<double> ms;
    Truth t;
    for (int k = 0; k < repeats; ++k) {
      t = oracle.evaluate(gbuffer, run.light, run.band);
      ms.push_back(1e3 * t.seconds);
    }
    long edge = 0;
    for (std::size_t i = 0; i < t.valid.size(); ++i) edge += t.valid[i] && !t.interior[i];
    cost.runs.push_back({run.what, median(ms), t.rays, edge});
  }
  return cost;
}

}  // namespace shadowlab
