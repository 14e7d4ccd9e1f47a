#include "app/bench_figures.h"

#include <algorithm>
#include <cmath>

#include "renderer/moments_pass.h"
#include "renderer/vsm_params.h"

namespace shadowlab {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

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
      t.format = p.get_choice("vsm.format");
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

}  // namespace shadowlab
