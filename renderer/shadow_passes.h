// The shadow techniques, registered once: which pass serves a feature's technique under a light type,
// and which shader files its includes default to. Adding a technique: a ShadowPass subclass, a value
// below, and one entry in shadow_passes.cpp.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/technique_params.h"

namespace shadowlab {

// What the shadow pass stores: one depth per texel (depth texture, compared in the lit pass; a cube map
// of distances for a point light) or the first two moments of depth (colour texture, filtered, read
// through Chebyshev's bound). ShadowVolumes has no shadow map: stencil shadow volumes from adjacency.
// MomentShadowMaps: four power moments (RGBA32F) read through the Hamburger bound (renderer/msm_pass.h).
// CascadedShadowMaps: a directional light's depth maps, one per slice of the camera's view range
// (renderer/cascade_pass.h).
enum class ShadowTechnique { Depth, Moments, ShadowVolumes, MomentShadowMaps, CascadedShadowMaps };

class ShadowPass;

struct ShadowPassEntry {
  ShadowTechnique technique;
  bool (*serves)(LightType light);
  // Virtual include name -> file under the data folder, e.g. "lab/visibility.glsl" -> a shadow test.
  std::map<std::string, std::string> (*default_includes)(LightType light);
  std::unique_ptr<ShadowPass> (*make)();
};

// The entry serving this technique and light type (every pair has one).
const ShadowPassEntry& shadow_pass_entry(ShadowTechnique technique, LightType light);

}  // namespace shadowlab
