#include "labs/check.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

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
  if (renderer.light_type() != LightType::Directional) {
    light.positional = true;
    light.position = renderer.light_position();
    const int size = std::max(renderer.shadow_map_size(), 1);
    // The angle one texel spans at the map's centre: a spot's map covers 2 tan(cone) over `size` texels,
    // each 90-degree cube face 2 tan(45 deg) = 2.
    const float extent = renderer.light_type() == LightType::Spot
                             ? 2.0f * std::tan(glm::radians(renderer.spot_cone_deg()))
                             : 2.0f;
    light.texel_angle = std::atan(extent / static_cast<float>(size));
    light.image_x = renderer.light_view().image_x;
    light.image_y = renderer.light_view().image_y;
    return light;
  }
  light.positional = false;
  light.to_light = renderer.to_light();
  light.image_x = renderer.light_view().image_x;
  light.image_y = renderer.light_view().image_y;
  light.texel_world_size = renderer.light_view().world_size.x / static_cast<float>(renderer.shadow_map_size());
  return light;
}

double interior_agreement(const Metrics& m) {
  const double lit = static_cast<double>(m.interior_lit), shadowed = static_cast<double>(m.interior_shadowed);
  if (lit + shadowed <= 0.0) return 0.0;  // nothing graded agrees with nothing
  return 1.0 - (m.acne_rate * lit + m.leak_rate * shadowed) / (lit + shadowed);
}

OrbitCamera camera_looking_at(const glm::vec3& eye, const glm::vec3& target, float near_plane, float far_plane) {
  OrbitCamera cam;
  const glm::vec3 d = eye - target;
  cam.target = target;
  cam.distance = glm::length(d);
  cam.pitch_deg = glm::degrees(std::asin(d.y / cam.distance));
  cam.yaw_deg = glm::degrees(std::atan2(d.x, d.z));
  cam.near_plane = near_plane;
  cam.far_plane = far_plane;
  return cam;
}

CheckContext::Measurement CheckContext::measure(const ParamSet& params, const LabHooks& hooks, const std::string& name,
                                                const Bounds* view, const BandSpec& band, int width, int height,
                                                const OrbitCamera* camera) {
  using clock = std::chrono::steady_clock;
  Measurement m;
  if (!renderer.set_lab(hooks)) throw std::runtime_error(renderer.shader_error());
  if (uploaded_ != scene_) {
    renderer.set_scene(*scene_);
    uploaded_ = scene_;
  }
  FrameRequest request;
  request.camera = camera ? *camera : OrbitCamera::framing(view ? *view : scene_->bounds());
  request.width = width;
  request.height = height;
  request.gbuffer = true;
  const auto t0 = clock::now();
  renderer.render(params, request);
  m.visibility = renderer.read_visibility();
  GBuffer gbuffer = renderer.read_gbuffer();
  if (renderer.light_type() == LightType::Spot) {
    const float cos_graded = std::cos(glm::radians(renderer.spot_cone_deg() - kSpotConeMarginDeg));
    for (std::size_t i = 0; i < gbuffer.position.size(); ++i) {
      const glm::vec3 d = gbuffer.position[i] - renderer.light_position();
      if (gbuffer.covered[i] && glm::dot(glm::normalize(d), renderer.spot_direction()) < cos_graded) gbuffer.covered[i] = 0;
    }
  }
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
