#include "renderer/shadowed_light.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "renderer/billboards.h"
#include "renderer/depth_map_pass.h"

namespace shadowlab {

// Everything a light's map is drawn from. A further light's holds no parameter values: moving the sun (or
// changing its technique's settings) leaves the other maps alone.
struct ShadowedLight::Inputs {
  std::vector<std::pair<std::string, double>> params;  // the frame light's: those declared kInvalidatesShadowMap
  glm::mat4 light_view{1.0f}, light_projection{1.0f};
  glm::vec3 light_position{0.0f};
  LightType light_type = LightType::Directional;
  int cull = 0;
  glm::vec3 billboard_eye{0.0f};  // the camera, with billboards: a wrong shadow pass may turn them to it
  long scene = 0, targets = 0;
  std::vector<int> programs;       // the pass's (and billboards') program generations
  std::vector<float> pass_inputs;  // what else the pass says its map depends on (ShadowPass::frame_inputs)
  bool operator==(const Inputs&) const = default;
};

ShadowedLight ShadowedLight::frame_light(std::string name) {
  ShadowedLight light;
  light.spec_.name = std::move(name);
  light.spec_.pass_name = "shadow";
  light.inputs_ = std::make_unique<Inputs>();
  light.scratch_ = std::make_unique<Inputs>();
  return light;
}

ShadowedLight::ShadowedLight(ShadowedLightSpec spec)
    : spec_(std::move(spec)),
      pass_(std::make_unique<DepthMapPass>(spec_.pass_name)),
      inputs_(std::make_unique<Inputs>()),
      scratch_(std::make_unique<Inputs>()) {}
ShadowedLight::~ShadowedLight() = default;
ShadowedLight::ShadowedLight(ShadowedLight&&) noexcept = default;
ShadowedLight& ShadowedLight::operator=(ShadowedLight&&) noexcept = default;

void ShadowedLight::set_pass(std::unique_ptr<ShadowPass> pass) {
  pass_ = std::move(pass);
  inputs_valid_ = false;
  ++targets_generation_;
}

bool ShadowedLight::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  inputs_valid_ = false;
  ++targets_generation_;
  return pass_->set_includes(includes, rules);
}

void ShadowedLight::for_each_program(const std::function<void(ReloadableProgram&)>& f) const {
  if (pass_) pass_->for_each_program(f);
}

void ShadowedLight::place(const PassContext& ctx, const Placement& placement) {
  light_ = spec_.place(ctx.params, ctx.scene.bounds(), ctx.camera_view);
  light_.scene_position = placement.to_scene(light_.position);
}

bool ShadowedLight::ensure_targets(const ParamSet& params) {
  if (!pass_->ensure_targets(params)) return false;
  ++targets_generation_;
  return true;
}

void ShadowedLight::inputs_of(const PassContext& ctx, long scene_generation, Inputs& in) const {
  if (is_frame_light()) ctx.params.values_invalidating(kInvalidatesShadowMap, in.params);
  in.light_view = light_.view.view;
  in.light_projection = light_.view.projection;
  in.light_position = light_.position;
  in.light_type = light_.type;
  in.cull = ctx.cull;
  in.billboard_eye = ctx.billboards ? glm::vec3(glm::inverse(ctx.camera_view)[3]) : glm::vec3(0.0f);
  in.scene = scene_generation;
  in.targets = targets_generation_;
  in.programs.clear();
  pass_->for_each_program([&](ReloadableProgram& p) { in.programs.push_back(p.generation()); });
  if (ctx.billboards) ctx.billboards->for_each_program([&](ReloadableProgram& p) { in.programs.push_back(p.generation()); });
}

void ShadowedLight::draw_map_if_changed(PassContext& ctx, long scene_generation) {
  // Compared in place, in storage kept from frame to frame: a still frame allocates nothing.
  inputs_of(ctx, scene_generation, *scratch_);
  pass_->frame_inputs(ctx, scratch_->pass_inputs);
  if (inputs_valid_ && *inputs_ == *scratch_) return;
  pass_->draw_map(ctx);
  ++(is_frame_light() ? ctx.stats.shadow_passes : ctx.stats.flashlight_shadow_passes);
  ++map_updates_;
  // Programs a pass builds on first use (a blur method's) count from now on.
  inputs_of(ctx, scene_generation, *scratch_);
  std::swap(inputs_, scratch_);
  inputs_valid_ = true;
}

void ShadowedLight::update(PassContext& ctx, const Placement& placement, long scene_generation) {
  place(ctx, placement);
  ensure_targets(ctx.params);
  PassContext light_ctx{ctx.scene,          ctx.gpu_scene,    ctx.params,         light_,
                        ctx.stats,          ctx.timer,        ctx.empty_vao,      ctx.cull,
                        ctx.camera_view,    ctx.camera_projection, ctx.infinite_far_plane, ctx.gbuffer,
                        ctx.cascade_view,   ctx.cascade_projection, ctx.cascade_splits, ctx.cascade_fit};
  draw_map_if_changed(light_ctx, scene_generation);
}

std::vector<float> ShadowedLight::read_depth(int* size) const { return pass_->read_depth(size); }
std::vector<std::uint8_t> ShadowedLight::map_image(int* size) const { return pass_->image(size); }

void ShadowedLight::bind_lit_inputs(const ParamSet& params, const LitUniforms::ShadowedLights::Entry& u, int unit) const {
  const glm::mat4& proj = light_.view.projection;  // near and far back from a perspective matrix
  u.tex_matrix.set(clip_to_texture() * light_.view.view_projection());
  u.position.set(light_.position);
  u.direction.set(light_.spot_direction);
  u.cos_cone.set(std::cos(glm::radians(light_.spot_cone_deg)));
  u.near.set(proj[3][2] / (proj[2][2] - 1.0f));
  u.far.set(proj[3][2] / (proj[2][2] + 1.0f));
  u.texel_angle.set(light_.texel_angle(std::max(pass_->size(), 1)));
  u.bias_slope.set(spec_.slope_bias(params));
  u.intensity.set(spec_.intensity(params));
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, static_cast<const DepthMapPass&>(*pass_).texture());
  glBindSampler(static_cast<GLuint>(unit), 0);
  u.map.set(unit);
}

}  // namespace shadowlab
