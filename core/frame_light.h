// The frame's light, CPU only: its type, its direction or position from the parameters, the view and
// projection of its shadow map (a feature's fit for a directional light, a spot's cone, a point light's
// six faces). The light-type decisions of a frame live here, in one place.
#pragma once

#include <functional>
#include <optional>

#include <glm/glm.hpp>

#include "core/light.h"
#include "core/params.h"
#include "core/placement.h"
#include "core/technique_params.h"

namespace shadowlab {

// How a directional light's view and projection are fitted to the scene (default: fit_light_ortho).
using LightFit = std::function<LightView(const Bounds& bounds, const glm::vec3& to_light)>;

struct FrameLight {
  LightType type = LightType::Directional;
  // Toward a directional light; for spot and point lights, from the scene's centre toward the light
  // (for display: their lit pass uses the position).
  glm::vec3 to_light{0, 1, 0};
  glm::vec3 position{0.0f};  // spot and point lights: light.position_* in the local frame (what the GPU uses)
  glm::vec3 scene_position{0.0f};  // the same in the scene's frame (light.position_* as given)
  glm::vec3 spot_direction{0, -1, 0};
  float spot_cone_deg = 45.0f;
  // light.size as given: a directional light's angular diameter in degrees, a spot or point light's
  // radius in the scene's world units (0: a point, hard shadows).
  float size = 0.0f;
  // The size as oracle/soft_truth.h's evaluate_soft takes it (radians for a directional light, the
  // scene frame's units for a positional one).
  float soft_truth_size() const;
  LightView view;        // the shadow map's view and projection (a point light: face 0's, for display)
  CubeLightViews cube;   // a point light's six faces

  // From the parameters: `pinned` is a feature's fixed light type (else light.type decides), `fit` a
  // directional light's fit (empty: fit_light_ortho). A spot aims at the scene's centre with the
  // half-angle light.cone_deg. Fields the new type does not use keep their last values. `bounds` is the
  // scene's box in the local frame; the position parameters are converted with `placement`, so every
  // matrix here (and a lab's fit) is computed on the small numbers of the local frame.
  void update(const ParamSet& params, const Bounds& bounds, std::optional<LightType> pinned, const LightFit& fit,
              const Placement& placement = {});

  // A fixed filter matched to this light's size (pcf.match_light, vsm.match_light): the radius r, in
  // texels of a map `map_size` wide, of the kernel (2r + 1 texels across) that spans the penumbra a
  // blocker `distance` (local units) above its receiver casts: 2 distance tan(size / 2) across, for a
  // sun. Right at that distance only: nearer contacts get too wide a penumbra, farther ones too narrow
  // (what PCSS measures per pixel instead). -1 where there is nothing to match: no size, or a spot or
  // point light (their texels have no single world size). At most kMaxMatchedFilterRadius (25 x 25 taps:
  // PCF's loops are unrolled when its radius is compiled in).
  static constexpr int kMaxMatchedFilterRadius = 12;
  int matched_filter_radius(float distance, int map_size) const;

  // xyz the position (w = 1) or the direction toward the light (w = 0).
  glm::vec4 vector4() const;
  // The angle one texel of a map `map_size` wide spans at the map's centre: a spot's 2 tan(cone) / size,
  // a cube face's 2 tan(45 deg) / size; 0 for a directional light (its texels have a world size).
  float texel_angle(int map_size) const;
};

}  // namespace shadowlab
