// One shadowed light beside the frame's own light (the sun): an entry of Features::lights as the renderer
// holds it. Each entry has its own light (ShadowedLightSpec::place), its own perspective depth map
// (DepthMapPass), redrawn only when what it was last drawn from changes (its light, the casters, its
// targets, its programs, the culling; not the sun's parameters), and its own lit uniforms
// (LitUniforms::ShadowedLights::Entry, read by shaders/shadow/shadowed_lights.glsl). The renderer keeps a
// list of them: a further light is a further entry, no new member.
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

class DepthMapPass;

class ShadowedLight {
 public:
  explicit ShadowedLight(ShadowedLightSpec spec);
  ~ShadowedLight();
  ShadowedLight(ShadowedLight&&) noexcept;
  ShadowedLight& operator=(ShadowedLight&&) noexcept;

  const std::string& name() const { return spec_.name; }
  // Its map's programs, built with the frame's includes; false on a shader error.
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules);
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) const;
  // Makes the next update draw the map even if nothing it reads changed.
  void invalidate() { inputs_valid_ = false; }
  // This frame: the light from its spec (in the frame's local frame: ctx.scene's box, ctx.camera_view;
  // scene_position converted with `placement`), its targets, and its map unless everything it was last
  // drawn from is unchanged (`scene_generation` bumps with every scene). Counts a drawn map in
  // ctx.stats.flashlight_shadow_passes and in map_updates().
  void update(PassContext& ctx, const Placement& placement, long scene_generation);

  // The last frame's light (local frame but for scene_position), its map and what drew it.
  const FrameLight& light() const { return light_; }
  const ShadowPass& pass() const;
  ShadowPass& pass();
  long map_updates() const { return map_updates_; }
  // Its map's depths, bottom row first, and as a picture (what its debug quad shows), top row first.
  std::vector<float> read_depth(int* size) const;
  std::vector<std::uint8_t> map_image(int* size) const;

  // Sets its lit uniforms (each where the program has it: an answer may leave some unused) and binds its
  // map on texture unit `unit`.
  void bind_lit_inputs(const ParamSet& params, const LitUniforms::ShadowedLights::Entry& u, int unit) const;

 private:
  struct Inputs;
  ShadowedLightSpec spec_;
  std::unique_ptr<DepthMapPass> pass_;
  FrameLight light_;
  // What the map was last drawn from, and this frame's, compared in place (a still frame allocates nothing).
  std::unique_ptr<Inputs> inputs_, scratch_;
  bool inputs_valid_ = false;
  long targets_generation_ = 0;
  long map_updates_ = 0;
};

}  // namespace shadowlab
