#include "renderer/shadowed_light.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "renderer/depth_map_pass.h"

namespace shadowlab {

// Everything a shadowed light's map is drawn from: its light, the casters, its targets, its programs and
// the culling. Not the sun's parameters: moving the sun (or only this light) leaves the other's map alone.
struct ShadowedLight::Inputs {
  glm::mat4 light_view{1.0f}, light_projection{1.0f};
  int cull = 0;
  long scene = 0, targets = 0;
  std::vector<int> programs;
  bool operator==(const Inputs&) const = default;
};

ShadowedLight::ShadowedLight(ShadowedLightSpec spec)
    : spec_(std::move(spec)),
      pass_(std::make_unique<DepthMapPass>(spec_.pass_name)),
      inputs_(std::make_unique<Inputs>()),
      scratch_(std::make_unique<Inputs>()) {}
ShadowedLight::~ShadowedLight() = default;
ShadowedLight::ShadowedLight(ShadowedLight&&) noexcept = default;
ShadowedLight& ShadowedLight::operator=(ShadowedLight&&) noexcept = default;

bool ShadowedLight::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  inputs_valid_ = false;
  ++targets_generation_;
  return pass_->set_includes(includes, rules);
}

void ShadowedLight::for_each_program(const std::function<void(ReloadableProgram&)>& f) const {
  pass_->for_each_program(f);
}

const ShadowPass& ShadowedLight::pass() const { return *pass_; }
ShadowPass& ShadowedLight::pass() { return *pass_; }

void ShadowedLight::update(PassContext& ctx, const Placement& placement, long scene_generation) {
  light_ = spec_.place(ctx.params, ctx.scene.bounds(), ctx.camera_view);
  light_.scene_position = placement.to_scene(light_.position);
  if (pass_->ensure_targets(ctx.params)) ++targets_generation_;
  Inputs& in = *scratch_;
  in.light_view = light_.view.view;
  in.light_projection = light_.view.projection;
  in.cull = ctx.cull;
  in.scene = scene_generation;
  in.targets = targets_generation_;
  in.programs.clear();
  pass_->for_each_program([&](ReloadableProgram& p) { in.programs.push_back(p.generation()); });
  if (inputs_valid_ && *inputs_ == in) return;
  // The same frame's context with this light as its light (and no billboards: they follow the sun).
  PassContext light_ctx{ctx.scene,          ctx.gpu_scene,    ctx.params,         light_,
                        ctx.stats,          ctx.timer,        ctx.empty_vao,      ctx.cull,
                        ctx.camera_view,    ctx.camera_projection, ctx.infinite_far_plane, ctx.gbuffer,
                        ctx.cascade_view,   ctx.cascade_projection, ctx.cascade_splits, ctx.cascade_fit};
  pass_->draw_map(light_ctx);
  ++ctx.stats.flashlight_shadow_passes;
  ++map_updates_;
  std::swap(inputs_, scratch_);
  inputs_valid_ = true;
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
  glBindTexture(GL_TEXTURE_2D, pass_->texture());
  glBindSampler(static_cast<GLuint>(unit), 0);
  u.map.set(unit);
}

}  // namespace shadowlab
