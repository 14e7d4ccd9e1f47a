// A shadowed light as the renderer holds it: its light this frame, its shadow pass (its map) and what that
// map was last drawn from. Every shadowed light is one: the renderer keeps them in one list
// (Renderer::lights()), entry 0 the frame's own light (the sun, or the spot or point light the parameters
// and features make it) drawn by the features' technique pass, then one entry per Features::lights spec
// (ShadowedLightSpec: lab 15's flashlight), each a perspective depth map (DepthMapPass). A further light is
// a further entry, no new member anywhere.
//
// The two kinds differ only in what places them and how the lit pass reads them:
//   - the frame light is placed by the renderer (FrameLight::update, from the parameters and the features'
//     fit); its map also depends on the parameters declared kInvalidatesShadowMap and on the billboards; the
//     lit pass reads it through its technique (ShadowPass::lit_bind, "lab/visibility.glsl");
//   - a further light is placed by its spec; the lit pass reads it through shaders/shadow/shadowed_lights.glsl
//     (bind_lit_inputs below), combined with the frame light's term in "lab/combine.glsl".
// Either map is redrawn only when what it was drawn from changes: moving one light leaves the others' maps
// alone.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/frame_light.h"
#include "core/shadowed_light_spec.h"
#include "renderer/shadow_pass.h"

namespace shadowlab {

class ShadowedLight {
 public:
  // The frame's own light, named `name` on its debug quad beside further lights; its pass comes with the
  // features (set_pass).
  static ShadowedLight frame_light(std::string name);
  // A further light: placed by `spec`, a perspective depth map.
  explicit ShadowedLight(ShadowedLightSpec spec);
  ~ShadowedLight();
  ShadowedLight(ShadowedLight&&) noexcept;
  ShadowedLight& operator=(ShadowedLight&&) noexcept;

  const std::string& name() const { return spec_.name; }
  bool is_frame_light() const { return !spec_.place; }

  // Its pass: a new technique's for the frame light (its map is drawn on the next frame); null before one.
  void set_pass(std::unique_ptr<ShadowPass> pass);
  bool has_pass() const { return pass_ != nullptr; }
  const ShadowPass& pass() const { return *pass_; }
  ShadowPass& pass() { return *pass_; }
  // Its map's programs, built with the frame's includes; false on a shader error.
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules);
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) const;
  // Makes the next update draw the map even if nothing it reads changed.
  void invalidate() { inputs_valid_ = false; }

  // Its light this frame, in the frame's local frame but for scene_position. The frame light's is placed
  // in place by the renderer (FrameLight::update keeps fields its type does not use); a further light's
  // by place().
  FrameLight& light() { return light_; }
  const FrameLight& light() const { return light_; }
  // A further light: from its spec, the parameters, the scene's box and the camera (ctx.scene,
  // ctx.camera_view: the local frame); scene_position converted with `placement`.
  void place(const PassContext& ctx, const Placement& placement);
  // Its targets for these parameters; true when they were (re)allocated (the map is then drawn again).
  bool ensure_targets(const ParamSet& params);
  // Draws its map unless everything it was last drawn from is unchanged: its light, the casters
  // (`scene_generation` bumps with every scene), its targets, its programs (and the billboards'), the
  // culling, what its pass says (ShadowPass::frame_inputs) and, for the frame light, the parameters
  // declared kInvalidatesShadowMap. `ctx.light` must be this light (the frame's context for the frame
  // light; a copy with this light for a further one, update()). Counts a drawn map in map_updates() and
  // in ctx.stats (shadow_passes for the frame light, flashlight_shadow_passes for the others).
  void draw_map_if_changed(PassContext& ctx, long scene_generation);
  // A further light, this frame: place(), ensure_targets(), then its map in the frame's context with this
  // light as its light (and no billboards: they follow the frame light).
  void update(PassContext& ctx, const Placement& placement, long scene_generation);

  long map_updates() const { return map_updates_; }
  // Its map's depths, bottom row first, and as a picture (what its debug quad shows), top row first.
  std::vector<float> read_depth(int* size) const;
  std::vector<std::uint8_t> map_image(int* size) const;

  // A further light's lit uniforms (each where the program has it: an answer may leave some unused), its
  // map bound on texture unit `unit`.
  void bind_lit_inputs(const ParamSet& params, const LitUniforms::ShadowedLights::Entry& u, int unit) const;

 private:
  ShadowedLight() = default;
  struct Inputs;
  void inputs_of(const PassContext& ctx, long scene_generation, Inputs& in) const;

  ShadowedLightSpec spec_;  // the frame light's has a name only
  std::unique_ptr<ShadowPass> pass_;
  FrameLight light_;
  // What the map was last drawn from, and this frame's, compared in place (a still frame allocates nothing).
  std::unique_ptr<Inputs> inputs_, scratch_;
  bool inputs_valid_ = false;
  long targets_generation_ = 0;
  long map_updates_ = 0;
};

}  // namespace shadowlab
