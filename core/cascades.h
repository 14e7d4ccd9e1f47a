// Cascaded shadow maps, CPU side: the camera's view range split into cascades, and one ortho light box
// per cascade. The split distances and the box fit are lab 12's exercise; the functions here are its
// solution, which the renderer uses unless a feature gives its own (Features::cascade_splits,
// Features::cascade_fit).
//
//   splits   practical split scheme (Zhang et al., "Parallel-split shadow maps"): the blend
//            lambda * logarithmic + (1 - lambda) * uniform of the two classic schemes
//   box      the bounding sphere of the cascade's slice of the view frustum (its radius depends only on
//            the slice, not on where the camera looks: no shimmer when the camera turns), its centre
//            snapped to whole texels in the light's image plane (no crawl when the camera moves); the
//            depth range is the scene's extent along the light, the same for every cascade
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/light.h"
#include "core/params.h"
#include "core/scene.h"

namespace shadowlab {

inline constexpr int kMaxCascades = 8;

// Distances from the camera (view depth) bounding the cascades: count + 1 values, the first the near
// plane, the last the far plane; cascade i covers [splits[i], splits[i + 1]].
using CascadeSplitFn = std::function<std::vector<float>(float near_plane, float far_plane, int count, float lambda)>;
// One cascade's light view: the eight corners of its slice of the camera frustum (world space), the
// direction toward the light, the cascade map's texels per side and the scene's box (for the depth range).
using FrustumCorners = std::array<glm::vec3, 8>;
using CascadeFitFn =
    std::function<LightView(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene)>;

// The solution: C_i = lambda * n (f / n)^(i / N) + (1 - lambda) * (n + (f - n) i / N).
std::vector<float> practical_splits(float near_plane, float far_plane, int count, float lambda);
// The solution: the slice's bounding sphere (centre the corners' mean, radius the largest distance to
// it), a square box one texel wider than the sphere on every side (map_size texels of 2 r / (map_size - 2)
// each: the snap moves the box by up to a texel), its centre snapped down to whole texels along the
// light's image axes; depth over the scene's box.
LightView fit_cascade_sphere(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene);

// The corners of the camera frustum between view depths `near_depth` and `far_depth` (> 0): near
// face first (x-y-, x+y-, x-y+, x+y+), then the far face in the same order.
FrustumCorners frustum_slice(const glm::mat4& camera_view, const glm::mat4& camera_projection, float near_depth,
                             float far_depth);

// Texels per side of each cascade's map when `count` cascades share the texels of one map
// `budget` x `budget`: floor(budget / sqrt(count)), so the comparison with one map is at equal memory.
int cascade_map_size(int budget, int count);

// One frame's cascades.
struct CascadeFrame {
  int count = 0;
  int map_size = 0;           // per cascade
  std::vector<float> splits;  // count + 1 view depths (as the split function returned them)
  std::vector<LightView> views;
  glm::mat4 camera_view{1.0f};  // the camera the cascades were fitted to (view depth = -(V p).z)
  float near_depth = 0.0f, far_depth = 0.0f;  // the range that was split: the camera's near and far planes

  // The cascade a world point is shaded from (as shaders/csm/visibility.glsl chooses it): the first
  // whose far split lies beyond the point's view depth, or -1 beyond the last.
  int cascade_of(const glm::vec3& world) const;
};

// The cascades for a camera: its near..far range split by `splits`, one box
// per slice by `fit` (either empty: the solution's).
CascadeFrame compute_cascades(const glm::mat4& camera_view, const glm::mat4& camera_projection, const glm::vec3& to_light,
                              const Bounds& scene, int count, float lambda, int budget, const CascadeSplitFn& splits,
                              const CascadeFitFn& fit);

// The csm.* parameters (renderer_params.cpp), declared by the features that use cascades.
std::vector<ParamSpec> csm_param_specs();

namespace param {
extern const IntParam csm_count;
extern const FloatParam csm_lambda;
extern const FloatParam csm_blend;
extern const BoolParam csm_show_cascades;
}  // namespace param

}  // namespace shadowlab
