#include "renderer/renderer.h"

#include <chrono>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/billboards.h"
#include "renderer/cube_shadow_pass.h"
#include "renderer/debug_views.h"
#include "renderer/lit_pass.h"
#include "renderer/moments_pass.h"
#include "renderer/shadow_volume_pass.h"
#include "renderer/ssao_pass.h"
#include "core/vsm_params.h"

namespace shadowlab {

// Everything a shadow map is drawn from. The parameters are the declared ones whose invalidation bits
// include kInvalidatesShadowMap (a new parameter needs only to declare the bit); the rest is what the
// pass reads besides parameters: the light, the casters, the targets, the programs and the culling a
// feature may decide.
namespace {
// The surfaces' material when a feature gives none: the vertex colour.
constexpr const char* kMaterialInclude = "lab/material.glsl";
constexpr const char* kPlainMaterial = "shaders/material/plain.glsl";
}  // namespace

std::map<std::string, std::string> Renderer::default_includes(ShadowTechnique technique, LightType light) {
  auto includes = shadow_pass_entry(technique, light).default_includes(light);
  includes.emplace(kMaterialInclude, kPlainMaterial);
  return includes;
}

Renderer::Renderer()
    : lit_(std::make_unique<LitPass>()),
      views_(std::make_unique<DebugViews>()),
      timer_(std::make_unique<PassTimer>()),
      empty_vao_(GlVertexArray::create()) {
  lights_.push_back(ShadowedLight::frame_light(kFrameLightName));
  // Room for every pass of a frame, so that a still frame allocates nothing: timed_passes first fills
  // when the query ring's results come back, which under load can be many frames after the first.
  constexpr std::size_t kPassesPerFrame = 32;
  stats_.passes.reserve(kPassesPerFrame);
  stats_.timed_passes.reserve(kPassesPerFrame);
  if (!set_features({})) throw std::runtime_error("cannot build the renderer's shaders:\n" + shader_error());
}

Renderer::~Renderer() = default;

void Renderer::set_scene(const Scene& scene) {
  source_ = scene;
  source_has_ground_ = has_ground(scene);
  scene_ = frame_scene(source_, ground_added_, blend_casts_);
  upload_scene();
}

Scene frame_scene(const Scene& scene, bool add_ground, bool blend_casts) {
  Scene out = with_ground(scene, add_ground);
  if (!blend_casts)
    for (Mesh& m : out.meshes)
      if (m.alpha_mode == AlphaMode::Blend) m.casts_shadow = false;
  return out;
}

bool adds_ground(const Scene& scene, const ParamSet& params) {
  return params.get(param::scene_ground) && !has_ground(scene);
}

Bounds frame_scene_bounds(const Scene& scene, const ParamSet& params) {
  Bounds box = scene.bounds();
  if (box.empty() || !adds_ground(scene, params)) return box;
  const glm::vec3 to_light =
      direction_from_angles(params.get(param::light_azimuth), params.get(param::light_elevation));
  const float height = box.extent().y;
  // Along the light's direction down to the ground: a point at height h moves h / tan(elevation) sideways.
  const glm::vec2 side(-to_light.x, -to_light.z);
  const float per_height = to_light.y > 1e-3f ? glm::length(side) / to_light.y : 1e3f;
  const glm::vec2 dir = glm::length(side) > 0.0f ? glm::normalize(side) : glm::vec2(0.0f);
  const float reach = std::min(per_height * height, 3.0f * height);
  Bounds out = box;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c = box.corner(i);
    out.extend(glm::vec3(c.x + dir.x * reach, box.min.y, c.z + dir.y * reach));
  }
  return out;
}

OrbitCamera frame_scene_camera(const Scene& scene, const ParamSet& params) {
  OrbitCamera cam = OrbitCamera::framing(frame_scene_bounds(scene, params));
  if (adds_ground(scene, params)) {
    const Bounds all = with_ground(scene, true).bounds();
    cam.far_plane = std::max(cam.far_plane, glm::length(cam.eye() - all.center()) + 0.5f * glm::length(all.extent()));
  }
  return cam;
}

bool Renderer::update_scene_options(const ParamSet& params) {
  const bool ground = params.get(param::scene_ground) && !source_has_ground_;
  const bool blend_casts = params.get(param::scene_blend_casts);
  if (ground == ground_added_ && blend_casts == blend_casts_) return false;
  ground_added_ = ground;
  blend_casts_ = blend_casts;
  scene_ = frame_scene(source_, ground_added_, blend_casts_);
  return true;
}

void Renderer::upload_scene() {
  local_scene_ = shadowlab::local_scene(scene_, placement_);
  gpu_scene_ = std::make_unique<GpuScene>(local_scene_);
  ++scene_generation_;
  for (ShadowedLight& light : lights_) light.pass().set_scene(local_scene_);
  views_->set_scene();
}

bool Renderer::set_features(const Features& features) {
  const LightType light = features.light ? *features.light : programs_light_;
  const bool ok = build_programs(features, light);
  frame_light().invalidate();
  stats_.moments_negative_variance = -1.0;
  return ok;
}

namespace {
// The radius of a filter matched to the light (pcf.match_light or vsm.match_light, whichever the
// parameters switch on), for the shadow pass; -1 when neither is on or there is nothing to match.
int matched_filter_radius(const ParamSet& params, const FrameLight& light, double scale) {
  const bool pcf = params.get(param::pcf_match_light);
  const bool vsm = params.get(param::vsm_match_light);
  if (!pcf && !vsm) return -1;
  const double distance = pcf ? params.get(param::pcf_match_distance) : params.get(param::vsm_match_distance);
  return light.matched_filter_radius(static_cast<float>(distance * scale), std::stoi(params.get(param::shadow_map_size)));
}

// Programs built from the same files report the same text: each text is said once.
void append_once(std::string& out, const std::string& text) {
  if (!text.empty() && out.find(text) == std::string::npos) out += text;
}
}  // namespace

bool Renderer::build_programs(const Features& features, LightType light) {
  if (features.lights.size() > static_cast<std::size_t>(kMaxShadowedLights)) {  // nothing built: the old features stay
    failed_build_error_ = std::to_string(features.lights.size()) + " shadowed lights: the lit pass takes at most " +
                          std::to_string(kMaxShadowedLights) + " (kMaxShadowedLights)\n";
    return false;
  }
  const ShadowPassEntry& entry = shadow_pass_entry(features.technique, light);
  IncludeMap includes;
  for (const auto& [name, file] : entry.default_includes(light)) includes[name] = file;
  includes[kMaterialInclude] = kPlainMaterial;
  // The lit pass reads its includes before the preprocessor: the SHADOWED_LIGHTS part needs its file always.
  includes["lab/combine.glsl"] = "shaders/shadow/combine_lights.glsl";
  // The selected shadow test's file in the visibility slot, unless the features name another there (a
  // student's version of that test, which reads the same uniforms).
  const ShadowTest* test = features.shadow_test.empty() ? nullptr : &find_shadow_test(features.shadow_test);
  if (test) includes["lab/visibility.glsl"] = test->file;
  for (const auto& [name, file] : features.includes) includes[name] = file;
  // The same technique keeps its pass (and targets); another gets a new one, kept only if it builds.
  std::unique_ptr<ShadowPass> fresh;
  if (shadow_entry_ != &entry) {
    fresh = entry.make();
    if (gpu_scene_) fresh->set_scene(local_scene_);
  }
  ShadowPass& pass = fresh ? *fresh : frame_light().pass();
  const std::vector<LitVariant> variants = pass.shape().lit_variants;
  bool ok = lit_->build(includes, features.include_rules, light, pass.shape(), static_cast<int>(features.lights.size()),
                        features.own_shadow_coords);
  std::vector<ShadowedLight> lights;
  for (const ShadowedLightSpec& spec : features.lights) {
    lights.emplace_back(spec);
    ok = lights.back().set_includes(includes, features.include_rules) && ok;
  }
  ok = pass.set_includes(includes, features.include_rules) && ok;
  std::unique_ptr<BillboardPass> billboards;
  if (!features.billboards.empty()) {
    billboards = std::make_unique<BillboardPass>();
    ok = billboards->set_includes(includes, features.include_rules) && ok;
  }
  std::unique_ptr<SsaoPass> ssao;
  if (features.ssao) {
    ssao = std::make_unique<SsaoPass>();
    ok = ssao->set_includes(includes, features.include_rules) && ok;
  }
  if (!ok) {
    // Kept now: a fresh pass that failed is dropped, and shader_error() walks only the kept passes.
    failed_build_error_.clear();
    const auto collect = [&](ReloadableProgram& program) { append_once(failed_build_error_, program.error()); };
    lit_->for_each_program(collect);
    pass.for_each_program(collect);
    if (billboards) billboards->for_each_program(collect);
    if (ssao) ssao->for_each_program(collect);
    for (const ShadowedLight& shadowed : lights) shadowed.for_each_program(collect);
    return false;
  }
  failed_build_error_.clear();
  pass.set_host_code(features.gl_host);
  lit_->set_host_code(features.gl_host);
  billboards_ = std::move(billboards);
  ssao_ = std::move(ssao);
  if (fresh) {
    frame_light().set_pass(std::move(fresh));
    shadow_entry_ = &entry;
  }
  lights_.erase(lights_.begin() + 1, lights_.end());  // the frame light stays: its pass keeps its targets
  for (ShadowedLight& further : lights) lights_.push_back(std::move(further));
  lit_->keep_only(variants);
  lit_->set_material(features.material_textures, features.material_params);
  views_->set_includes(includes, features.include_rules);
  features_ = features;
  shadow_test_ = test;
  programs_light_ = light;
  return true;
}

void Renderer::for_each_program(const std::function<void(ReloadableProgram&)>& f) const {
  lit_->for_each_program(f);
  views_->for_each_program(f);
  for (const ShadowedLight& light : lights_) light.for_each_program(f);
  if (billboards_) billboards_->for_each_program(f);
  if (ssao_) ssao_->for_each_program(f);
}

bool Renderer::poll_shader_files() {
  // A swapped program of the shadow pass changes its generation, an input of the shadow map.
  bool swapped = false;
  for_each_program([&](ReloadableProgram& program) { swapped = program.poll_files() || swapped; });
  return swapped;
}

std::string Renderer::shader_error() const {
  if (!failed_build_error_.empty()) return failed_build_error_;
  std::string out;
  for_each_program([&](ReloadableProgram& program) { append_once(out, program.error()); });
  return out;
}

std::string Renderer::shader_warnings() const {
  std::string out;
  for_each_program([&](ReloadableProgram& program) { append_once(out, program.warnings()); });
  return out;
}

void Renderer::invalidate_shadow_map() {
  for (ShadowedLight& light : lights_) light.invalidate();
}

void Renderer::set_lit_constants(bool on) { lit_->set_specialise(on); }
const LitConstants& Renderer::drawn_lit_constants() const { return lit_->drawn_constants(); }

void Renderer::set_timing(TimingMode mode) { timer_->set_mode(mode); }
TimingMode Renderer::timing() const { return timer_->mode(); }
bool Renderer::timers_work() const { return timer_->timers_work(); }

const FrameStats& Renderer::render(const ParamSet& params, const FrameRequest& request) {
  if (!gpu_scene_) throw std::logic_error("Renderer::render called before set_scene");
  const auto cpu_start = std::chrono::steady_clock::now();
  stats_.passes.clear();
  ++stats_.frames;
  timer_->begin_frame(stats_);

  // 1. The light: its type, direction or position from the sliders, its view and projection from the
  // features' fit (directional), the spot's cone or the point light's six faces.
  // In the local frame: the scene converted once per placement, the light's position each frame.
  Placement placement = placement_from(params);
  placement.offset += placement.scale * scene_.origin;  // the scene's own origin, moved and scaled with it
  const bool options_changed = update_scene_options(params);  // the ground plane, BLEND casters
  if (options_changed || !(placement == placement_)) {
    placement_ = placement;
    upload_scene();
  }
  FrameLight& light = frame_light().light();
  light.update(params, local_scene_.bounds(), features_.light, features_.light_fit, placement_);
  if (light.type != programs_light_) build_programs(features_, light.type);  // on failure the error shows
  ShadowPass& shadow = frame_light().pass();
  const ShadowPass::Shape& shape = shadow.shape();
  const int matched_radius = matched_filter_radius(params, light, placement_.scale);
  shadow.set_matched_radius(matched_radius);
  frame_light().ensure_targets(params);
  lit_->ensure_targets(request.width, request.height, request.gbuffer, shape.view_stencil, request.to_window,
                       request.window_framebuffer);
  PassContext ctx = frame_context(params, request, shape.view_stencil);
  annotations_.clear();
  ctx.annotations = &annotations_;
  if (billboards_ && shadow_entry_ == &shadow_pass_entry(ShadowTechnique::Depth, light.type)) {
    billboards_->set_points(features_.billboards, placement_);
    ctx.billboards = billboards_.get();
  }
  // What the lit pass reads besides the lights: the selected shadow test.
  const LitInputs lit_inputs{shadow_test_, matched_radius};
  ctx.lit_inputs = &lit_inputs;
  // The lit program compiled for what these parameters use (the technique's and the shadow test's few
  // settings as constants).
  shadow.lit_constants(params, lit_constants_);
  if (shadow_test_ && shadow_test_->constants)
    shadow_test_->constants(ShadowTestFrame{params, light, matched_radius, nullptr}, lit_constants_);
  lit_->use_constants(lit_constants_);

  // 2. Shadow pass(es): the map only when something it is drawn from changed; then what the camera's
  // view needs before it is lit (shadow volumes: the ambient and stencil passes).
  if (shape.has_map) frame_light().draw_map_if_changed(ctx, scene_generation_);
  // 2b. Each further shadowed light's own map, with its own inputs: moving one leaves the others' alone.
  for (std::size_t i = 1; i < lights_.size(); ++i) lights_[i].update(ctx, placement_, scene_generation_);
  ctx.lights = &lights_;
  if (shape.lit_first) ctx.timed(shape.lit_first->name, [&] { lit_->draw(ctx, shape.lit_first->variant); });
  shadow.draw_view_passes(ctx, ViewTarget{lit_->framebuffer(), lit_->width(), lit_->height()});

  // 3. Lit pass from the camera, reading the shadow map (or the moments, or the stencil).
  ctx.timed("lit", [&] { lit_->draw(ctx, shape.lit); });
  if (ctx.billboards) {
    ctx.timed("billboards", [&] {
      glBindFramebuffer(GL_FRAMEBUFFER, lit_->framebuffer());
      glViewport(0, 0, request.width, request.height);
      ctx.billboards->draw_view(ctx, params.get(param::billboard_show_shadow_quads));
    });
  }

  // 3b. Screen-space ambient occlusion over the lit picture, when the features ask for it.
  if (ssao_) ssao_->draw(ctx, ViewTarget{lit_->framebuffer(), lit_->width(), lit_->height()});

  // 4. Debug views.
  views_->draw(ctx, shadow, *lit_);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  stats_.cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start).count();
  return stats_;
}

PassContext Renderer::frame_context(const ParamSet& params, const FrameRequest& request, bool infinite_far_plane) {
  width_ = request.width;
  height_ = request.height;
  const OrbitCamera camera = to_local(request.camera, placement_);
  camera_view_ = camera.view();
  const float aspect = static_cast<float>(request.width) / static_cast<float>(request.height);
  // Shadow volumes reach to infinity: the camera's far plane goes there too (third row 0, 0, -1, -2n).
  camera_projection_ = infinite_far_plane ? glm::infinitePerspective(glm::radians(camera.fov_y_deg), aspect, camera.near_plane)
                                          : camera.projection(aspect);
  const int cull = features_.shadow_cull_override ? features_.shadow_cull_override(params) : params.index(param::shadow_cull);
  std::optional<OrbitCamera> cascade_camera;
  if (request.cascade_camera) cascade_camera = to_local(*request.cascade_camera, placement_);
  return {local_scene_,
          *gpu_scene_,
          params,
          frame_light().light(),
          stats_,
          *timer_,
          empty_vao_.id(),
          cull,
          camera_view_,
          camera_projection_,
          infinite_far_plane,
          request.gbuffer,
          cascade_camera ? cascade_camera->view() : camera_view_,
          cascade_camera ? cascade_camera->projection(aspect) : camera_projection_,
          &features_.cascade_splits,
          &features_.cascade_fit};
}

const ShadowedLight& Renderer::shadowed_light(const std::string& name) const {
  for (const ShadowedLight& light : lights_)
    if (light.name() == name) return light;
  throw std::logic_error("the features have no shadowed light named \"" + name + "\"");
}

int Renderer::shadow_map_size() const { return frame_light().pass().size(); }

void Renderer::present(GLuint framebuffer, int width, int height) const { lit_->present(framebuffer, width, height); }
std::vector<std::uint8_t> Renderer::read_color() const { return lit_->read_color(); }
std::vector<float> Renderer::read_visibility() const { return lit_->read_visibility(); }
GBuffer Renderer::read_gbuffer() const {
  GBuffer g = lit_->read_gbuffer();
  if (!placement_.is_identity())
    for (glm::vec3& p : g.position) p = placement_.to_scene(p);
  return g;
}
std::vector<float> Renderer::read_ao(bool blurred) const {
  if (!ssao_) throw std::logic_error("read_ao needs the features' SSAO (Features::ssao)");
  return ssao_->read_open(blurred);
}
std::vector<float> Renderer::read_shadow_depth(int* size) const { return frame_light().pass().read_depth(size); }
std::vector<std::uint8_t> Renderer::shadow_map_image(int* size) const { return frame_light().pass().image(size); }

std::vector<float> Renderer::read_cube_face(int face, int* size) const {
  const auto* cube = dynamic_cast<const CubeShadowPass*>(&frame_light().pass());
  if (!cube || face < 0 || face > 5) throw std::logic_error("read_cube_face needs a point light's cube shadow map");
  *size = cube->size();
  return cube->read_face(face);
}

std::vector<float> Renderer::read_moments(int* size) const {
  const auto* moments = dynamic_cast<const MomentsPass*>(&frame_light().pass());
  if (!moments) throw std::logic_error("read_moments needs the moments technique");
  *size = moments->size();
  return moments->read_moments();
}

MomentsTargetInfo Renderer::moments_targets() const {
  const auto* moments = dynamic_cast<const MomentsPass*>(&frame_light().pass());
  return moments ? moments->query_targets() : MomentsTargetInfo{};
}

VolumeTriangles Renderer::count_volume_triangles(bool caps) {
  auto* volumes = dynamic_cast<ShadowVolumePass*>(&frame_light().pass());
  if (!volumes || !lit_) throw std::logic_error("count_volume_triangles needs the shadow-volume technique and a frame");
  glBindFramebuffer(GL_FRAMEBUFFER, lit_->framebuffer());
  const VolumeTriangles count = volumes->count_triangles(frame_light().light().vector4(), caps, local_scene_.bounds());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return count;
}

std::vector<VolumeMeshReport> Renderer::volume_report() const {
  if (const auto* volumes = dynamic_cast<const ShadowVolumePass*>(&frame_light().pass())) return volumes->report();
  return views_->volume_report();
}

}  // namespace shadowlab
