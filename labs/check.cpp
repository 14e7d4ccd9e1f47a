#include "labs/check.h"

#include <chrono>

#include "renderer/image_io.h"

namespace shadowlab {

bool CheckResult::passed() const {
  if (!error.empty() || criteria.empty()) return false;  // a check that grades nothing cannot pass
  for (const auto& c : criteria)
    if (!c.passed()) return false;
  return true;
}

nlohmann::json CheckResult::to_json() const {
  nlohmann::json thresholds = nlohmann::json::object();
  nlohmann::json graded = metrics;
  for (const auto& c : criteria) {
    thresholds[c.metric] = {{c.direction == Criterion::kAtMost ? "max" : "min", c.limit}, {"why", c.why}};
    graded[c.metric] = c.value;
  }
  nlohmann::json j = {{"lab", lab},         {"slug", slug},         {"impl", impl_name(impl)}, {"passed", passed()},
                      {"metrics", graded},  {"thresholds", thresholds}, {"seconds", seconds}};
  j["parameters"] = parameters;
  if (!images.empty()) j["images"] = images;
  if (!error.empty()) j["error"] = error;
  return j;
}

CheckContext::CheckContext(Renderer& r, const Lab& l, Impl i, const Scene& default_scene, std::filesystem::path out)
    : renderer(r), lab(l), impl(i), out_dir(std::move(out)), scene_(&default_scene) {}

ParamSet CheckContext::params() const {
  ParamSet p = lab_params(lab);
  for (const auto& a : assignments) p.apply_assignment(a);
  return p;
}

void CheckContext::use_scene(const Scene& scene) {
  owned_scene_ = std::make_unique<Scene>(scene);
  scene_ = owned_scene_.get();
  oracle_.reset();
}

const Oracle& CheckContext::oracle() {
  if (!oracle_) oracle_ = std::make_unique<Oracle>(*scene_);
  return *oracle_;
}

OracleLight oracle_light(const Renderer& renderer) {
  OracleLight light;
  light.positional = false;
  light.to_light = renderer.to_light();
  light.image_x = renderer.light_view().image_x;
  light.image_y = renderer.light_view().image_y;
  light.texel_world_size = renderer.light_view().world_size.x / static_cast<float>(renderer.shadow_map_size());
  return light;
}

CheckContext::Measurement CheckContext::measure(const ParamSet& params, const LabHooks& hooks, const std::string& name,
                                                const Bounds* view, const BandSpec& band, int width, int height) {
  using clock = std::chrono::steady_clock;
  Measurement m;
  if (!renderer.set_lab(hooks)) throw std::runtime_error(renderer.shader_error());
  if (uploaded_ != scene_) {
    renderer.set_scene(*scene_);
    uploaded_ = scene_;
  }
  FrameRequest request;
  request.camera = OrbitCamera::framing(view ? *view : scene_->bounds());
  request.width = width;
  request.height = height;
  request.gbuffer = true;
  const auto t0 = clock::now();
  renderer.render(params, request);
  m.visibility = renderer.read_visibility();
  const GBuffer gbuffer = renderer.read_gbuffer();
  const auto t1 = clock::now();
  m.truth = oracle().evaluate(gbuffer, oracle_light(renderer), band);
  m.metrics = compare(m.truth, m.visibility);
  const auto t2 = clock::now();
  m.render_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  m.oracle_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  if (!out_dir.empty()) {
    const auto final_path = out_dir / (name + "_final.png");
    const auto diff_path = out_dir / (name + "_diff.png");
    write_png(final_path, width, height, renderer.read_color());
    write_png(diff_path, width, height, diff_image(m.truth, m.visibility));
    images.push_back(final_path.string());
    images.push_back(diff_path.string());
  }
  return m;
}

}  // namespace shadowlab
