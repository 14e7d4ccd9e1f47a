// The renderer's own parameters, declared once (CPU only, so CPU tests and tools can read them).
#include "core/params.h"

#include <stdexcept>

#include "core/placement.h"
#include "core/ao_params.h"
#include "core/technique_params.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace param {

const FloatParam light_azimuth{{"light.azimuth", "Light azimuth (deg)", ParamKind::Float, 35.0, 0.0, 360.0,
    "Direction of the light around the vertical axis.", {}, kInvalidatesShadowMap}};
const FloatParam light_elevation{{"light.elevation", "Light elevation (deg)", ParamKind::Float, 50.0, 1.0, 90.0,
    "Height of the light above the ground plane: low values give long shadows and grazing angles (acne).", {},
    kInvalidatesShadowMap}};
const FloatParam light_size{{"light.size", "Light size", ParamKind::Float, 0.0, 0.0, 10.0,
    "The light as a disk, as real lights are: a directional light's (the sun's) angular diameter in degrees, "
    "a spot or point light's radius in world units. 0 is a point (or a single direction): hard shadows. A "
    "sized light casts an umbra, which sees none of it, and a penumbra, which sees part; the checks then "
    "grade against the fraction of the disk each point sees.", {}}};
const ChoiceParam shadow_map_size{{"shadow.map_size", "Shadow map size", ParamKind::Choice, 2.0, 0.0, 4.0,
    "Texels per side of the shadow map: more texels, finer shadow edges, more memory and time.",
    {"256", "512", "1024", "2048", "4096"}, kInvalidatesShadowMap | kInvalidatesTargets}};
const ChoiceParam shadow_depth_format{{"shadow.depth_format", "Depth format", ParamKind::Choice, 1.0, 0.0, 2.0,
    "Precision of the stored depth: 16-bit fixed point shows acne sooner than 24-bit or 32-bit float.",
    {"16", "24", "32F"}, kInvalidatesShadowMap | kInvalidatesTargets}};
const FloatParam shadow_bias{{"shadow.bias", "Constant bias", ParamKind::Float, 0.005, 0.0, 0.1,
    "Subtracted from the fragment's light-space depth before the comparison: too small gives acne, too "
    "large peter-panning. In depth units of the light's projection ([0, 1]).", {}, kInvalidatesNothing, true}};
const FloatParam shadow_slope_bias{{"shadow.slope_bias", "Slope bias", ParamKind::Float, 0.0, 0.0, 20.0,
    "Extra bias that grows with the surface's tilt away from the light, in shadow-map texels per unit of "
    "tan(angle of incidence).", {}}};
const ChoiceParam shadow_cull{{"shadow.cull", "Shadow pass culling", ParamKind::Choice, 0.0, 0.0, 2.0,
    "Which faces the shadow pass skips. Culling front faces stores back faces, moving acne to faces that "
    "are unlit anyway (needs closed meshes).", {"none", "front", "back"}, kInvalidatesShadowMap}};
const BoolParam shadow_cull_casters{{"shadow.cull_casters", "Skip casters outside the light", ParamKind::Bool, 1.0,
    0.0, 1.0, "Shadow casters whose bounding box lies outside the light's volume (the ortho box, the spot's frustum, "
    "a cube face's frustum) are not drawn into the map: they could not write a texel. Off draws them all, "
    "for comparison (same map, more draws).", {}, kInvalidatesShadowMap}};
const FloatParam view_ambient{{"view.ambient", "Ambient", ParamKind::Float, 0.25, 0.0, 1.0,
    "Light that reaches shadowed surfaces too.", {}}};
const BoolParam view_debug_quad{{"view.debug_quad", "Show shadow map", ParamKind::Bool, 1.0, 0.0, 1.0,
    "A quad in the corner shows what the light sees (the shadow map's depths).", {}}};
const ChoiceParam view_debug_channel{{"view.debug_channel", "Shadow map channel", ParamKind::Choice, 0.0, 0.0, 4.0,
    "What the debug quad shows. all: the depth map (or, for variance shadow maps, E[z], E[z^2] and the "
    "variance side by side); one channel: that one alone. Without the moments technique every choice shows depth.",
    {"all", "depth", "moment 1", "moment 2", "variance"}, {}}};
const FloatParam view_debug_quad_size{{"view.debug_quad_size", "Shadow map quad size", ParamKind::Float, 0.25, 0.1, 1.0,
    "Side of the debug quad as a share of the view's height: enlarge it to read single texels.", {}}};
const BoolParam view_light_volume{{"view.light_volume", "Show the light's volume", ParamKind::Bool, 0.0, 0.0, 1.0,
    "Wireframe of what the shadow map covers: the fitted ortho box of a directional light or the frustum of "
    "a spot light (a point light's six frusta fill all space: nothing to draw).", {}}};
// Geometry-shader debug views; they cost nothing while off.
const BoolParam view_flat_normals{{"view.flat_normals", "Show flat normals (GS)", ParamKind::Bool, 0.0, 0.0, 1.0,
    "A geometry shader takes each triangle and emits it again with its face normal (the cross product of "
    "two edges) in place of the vertices' smooth normals; each triangle is drawn in that normal's colour "
    "(x red, y green, z blue), so the facets of a smooth-shaded mesh show.", {}}};
const BoolParam view_normals{{"view.normals", "Show normals (GS)", ParamKind::Bool, 0.0, 0.0, 1.0,
    "A geometry shader turns every triangle into three lines: each vertex and its normal.", {}}};
const BoolParam view_volumes{{"view.volumes", "Show shadow volumes (GS)", ParamKind::Bool, 0.0, 0.0, 1.0,
    "The shadow volumes' silhouette quads and caps, extruded by the geometry shader from adjacency, as "
    "wireframe. Builds the adjacency on first use.", {}}};
const BoolParam scene_ground{{"scene.ground", "Ground when missing", ParamKind::Bool, 1.0, 0.0, 1.0,
    "A scene with no surface of its own under it (no roughly horizontal receiver in the bottom quarter of its "
    "box covering a quarter of its footprint) gets a ground plane at the bottom of its box, four times its "
    "width, so its shadow falls on something. Scenes with a ground never get a second one.", {},
    kInvalidatesShadowMap}};
const BoolParam scene_blend_casts{{"scene.blend_casts", "BLEND materials cast shadows", ParamKind::Bool, 1.0, 0.0, 1.0,
    "Whether meshes whose glTF material is alphaMode BLEND (drawn blended after the opaque ones) cast "
    "shadows as solid casters, or none at all.", {}, kInvalidatesShadowMap}};

}  // namespace param

std::vector<ParamSpec> renderer_param_specs() {
  std::vector<ParamSpec> specs = specs_of(param::light_azimuth, param::light_elevation, param::light_size,
      param::shadow_map_size, param::shadow_depth_format, param::shadow_bias, param::shadow_slope_bias,
      param::shadow_cull, param::shadow_cull_casters, param::view_ambient, param::view_debug_quad,
      param::view_debug_channel, param::view_debug_quad_size, param::view_light_volume, param::view_flat_normals,
      param::view_normals, param::view_volumes, param::scene_ground, param::scene_blend_casts);
  for (ParamSpec& spec : placement_param_specs()) specs.push_back(std::move(spec));
  return specs;
}

namespace param {

const ChoiceParam vsm_format{{"vsm.format", "Moments format", ParamKind::Choice, 0.0, 0.0, 1.0,
    "Internal format of the moments texture. RG16F halves memory and bandwidth, but stores z to only "
    "about 5e-4 and E[z^2] - E[z]^2 cancels (often negative) in half precision.", {"RG32F", "RG16F"},
    kInvalidatesShadowMap | kInvalidatesTargets}};
const FloatParam vsm_min_variance{{"vsm.min_variance", "Minimum variance", ParamKind::Float, 2e-6, 1e-7, 1e-2,
    "Lower clamp of sigma^2 = E[z^2] - E[z]^2 in Chebyshev's bound. Float cancellation can make the difference "
    "zero or negative on flat receivers; too large a clamp lets light through thin shadows.", {},
    kInvalidatesNothing, true}};
const FloatParam vsm_bleed_delta{{"vsm.bleed_delta", "Light-bleeding cut (delta)", ParamKind::Float, 0.125, 0.0, 0.9,
    "Chebyshev bounds below delta become 0 and [delta, 1] is stretched to [0, 1]: removes the light that "
    "bleeds through stacked occluders, at the price of darker penumbrae.", {}}};
const BoolParam vsm_show_remap{{"vsm.show_remap", "Show where delta acts", ParamKind::Bool, 0.0, 0.0, 1.0,
    "Tints the pixels whose visibility the delta remap lowered: magenta, stronger where it removed more light.", {}}};
const IntParam vsm_blur_radius{{"vsm.blur_radius", "Blur radius (texels)", ParamKind::Int, 0.0, 0.0, 64.0,
    "Half-width of the separable Gaussian run over the moments (X then Y). 0 runs no blur pass and allocates "
    "no blur target.", {}, kInvalidatesShadowMap | kInvalidatesTargets}};
const FloatParam vsm_blur_sigma{{"vsm.blur_sigma", "Blur sigma (texels)", ParamKind::Float, 1.0, 0.25, 8.0,
    "Standard deviation of the Gaussian weights; keep the radius near 2-3 sigma or the kernel is cut off.", {},
    kInvalidatesShadowMap}};
const ChoiceParam vsm_blur_method{{"vsm.blur_method", "Blur method", ParamKind::Choice, 0.0, 0.0, 2.0,
    "How the Gaussian over the moments is computed; all three give the same moments (within 1e-4). "
    "separable: the taught shader (lab/blur.glsl, X then Y, one texel and one exp() per tap). fast: the same "
    "separable Gaussian, weights computed once on the CPU, each texel read once per 16 outputs (a compute shader; "
    "1.7-6x faster on llvmpipe for radii 1-16). brute2d: one pass over all (2r+1)^2 texels, for comparison.",
    {"separable", "fast", "brute2d"}, kInvalidatesShadowMap}};
const ChoiceParam vsm_warp{{"vsm.warp", "Depth warp", ParamKind::Choice, 0.0, 0.0, 1.0,
    "What the moments are of. none: depth z (VSM, two moments). exponential: EVSM, the moments of two warps, "
    "exp(c+ z) and -exp(-c- z) (four moments: the format's RGBA variant), and the smaller of their two "
    "Chebyshev bounds, which cuts light bleeding. Needs the moments and test shaders of lab 13.",
    {"none", "exponential"}, kInvalidatesShadowMap}};
const FloatParam vsm_evsm_exponent{{"vsm.evsm_exponent", "EVSM exponent c+", ParamKind::Float, 42.0, 1.0, 42.0,
    "c+ in the positive warp exp(c+ z), z in [0, 1]. Clamped to the format's range: 42 for 32-bit floats "
    "(2c = 84 < ln(FLT_MAX) = 88.7, room for the slope term), 5 for 16-bit (2c = 10 < ln(65504 / 2) = 10.4). "
    "Larger: less bleeding.",
    {}, kInvalidatesShadowMap}};
const FloatParam vsm_evsm_negative_exponent{{"vsm.evsm_negative_exponent", "EVSM exponent c-", ParamKind::Float, 42.0, 1.0, 42.0,
    "c- in the negative warp -exp(-c- z), z in [0, 1]. Clamped like c+: 42 for 32-bit floats (exp(-84) = 3e-37, "
    "the far plane's second moment, stays above FLT_MIN = 1.2e-38), 5 for 16-bit.",
    {}, kInvalidatesShadowMap}};
const BoolParam vsm_match_light{{"vsm.match_light", "Blur matched to the light", ParamKind::Bool, 0.0, 0.0, 1.0,
    "With light.size above 0 (a sun): instead of vsm.blur_radius and vsm.blur_sigma, a Gaussian as wide as "
    "the penumbra that a blocker vsm.match_distance above its receiver casts, 2 d tan(size / 2): the radius "
    "of a box that wide (up to 12 texels) and the box's own spread, sigma = (2r + 1) / sqrt(12). Right at "
    "that distance only, as PCF's matched kernel.", {}, kInvalidatesShadowMap | kInvalidatesTargets}};
const DoubleParam vsm_match_distance{{"vsm.match_distance", "Matched blocker height", ParamKind::Float, 1.0, 0.05, 10.0,
    "The blocker-to-receiver distance (world units) that vsm.match_light sizes the blur for.", {},
    kInvalidatesShadowMap}};
const FloatParam vsm_msm_moment_bias{{"vsm.msm_moment_bias", "MSM moment bias (alpha)", ParamKind::Float, 3e-5, 1e-7,
    1e-2, "Moment shadow maps: the share of (0.5, 0.5, 0.5, 0.5), the moments of half the weight at depth 0 and half "
    "at 1, mixed into the filtered ones, so the 3x3 Hankel solve stays defined in float32. Larger: more light bleeding; smaller: noise where the "
    "moments are nearly singular (flat receivers).", {}, kInvalidatesNothing, true}};

}  // namespace param

std::vector<ParamSpec> vsm_param_specs() {
  return specs_of(param::vsm_format, param::vsm_min_variance, param::vsm_bleed_delta, param::vsm_show_remap,
      param::vsm_blur_radius, param::vsm_blur_sigma, param::vsm_blur_method, param::vsm_warp, param::vsm_evsm_exponent, param::vsm_evsm_negative_exponent,
      param::vsm_match_light, param::vsm_match_distance, param::vsm_msm_moment_bias);
}

namespace param {

const ChoiceParam light_type{{"light.type", "Light type", ParamKind::Choice, 0.0, 0.0, 2.0,
    "Directional: parallel rays, an orthographic map. Spot: a perspective map from the light's position "
    "within its cone. Point: six 90-degree faces of a cube map storing the distance to the light.",
    {"directional", "spot", "point"}, kInvalidatesShadowMap | kInvalidatesTargets | kInvalidatesPrograms}};
const FloatParam light_position_x{{"light.position_x", "Light position x", ParamKind::Float, -0.6, -10.0, 10.0,
    "Where a spot or point light stands (world units).", {}, kInvalidatesShadowMap}};
const FloatParam light_position_y{{"light.position_y", "Light position y", ParamKind::Float, 3.0, 0.1, 12.0,
    "Height of a spot or point light above the ground.", {}, kInvalidatesShadowMap}};
const FloatParam light_position_z{{"light.position_z", "Light position z", ParamKind::Float, 0.2, -10.0, 10.0,
    "Where a spot or point light stands (world units).", {}, kInvalidatesShadowMap}};
const FloatParam light_cone_deg{{"light.cone_deg", "Spot cone half-angle (deg)", ParamKind::Float, 45.0, 5.0, 75.0,
    "Half the spot light's opening angle; it aims at the scene's centre. Wider cones spread the same texels "
    "over more of the scene.", {}, kInvalidatesShadowMap}};

}  // namespace param

std::vector<ParamSpec> light_param_specs() {
  return specs_of(param::light_type, param::light_position_x, param::light_position_y, param::light_position_z,
      param::light_cone_deg);
}

namespace param {

const ChoiceParam pcf_kernel{{"pcf.kernel", "PCF kernel", ParamKind::Choice, 1.0, 0.0, 4.0,
    "Taps per side of the percentage-closer filter: the comparison is averaged over N x N neighbouring "
    "texels (3 x 3 in the lecture).", {"1", "3", "5", "7", "9"}, kInvalidatesPrograms}};
const BoolParam pcf_hardware{{"pcf.hardware", "Hardware comparison", ParamKind::Bool, 0.0, 0.0, 1.0,
    "Read through a sampler2DShadow (GL_COMPARE_REF_TO_TEXTURE, linear): every tap becomes a bilinear "
    "2 x 2 PCF for free.", {}, kInvalidatesPrograms}};
const BoolParam pcf_match_light{{"pcf.match_light", "Kernel matched to the light", ParamKind::Bool, 0.0, 0.0, 1.0,
    "With light.size above 0 (a sun): instead of pcf.kernel, a kernel as wide as the penumbra that a blocker "
    "pcf.match_distance above its receiver casts, 2 d tan(size / 2) (up to 25 x 25 texels). Right at that "
    "distance only: where a blocker touches its receiver the penumbra drawn is too wide, under a tall one too "
    "narrow (PCSS measures the distance per pixel instead).", {}, kInvalidatesPrograms}};
const DoubleParam pcf_match_distance{{"pcf.match_distance", "Matched blocker height", ParamKind::Float, 1.0, 0.05, 10.0,
    "The blocker-to-receiver distance (world units) that pcf.match_light sizes the kernel for.", {},
    kInvalidatesPrograms}};
// Percentage-closer soft shadows (shaders/shadow/pcss.glsl): read by the lit pass as uniforms.
const IntParam pcss_blocker_samples{{"pcss.blocker_samples", "PCSS blocker search taps", ParamKind::Int, 6.0, 2.0, 16.0,
    "Taps per side of PCSS's blocker search: the depths in front of the point, averaged over the region of "
    "the map from which the light's disk can be hidden, give the blockers' mean distance.", {}}};
const IntParam pcss_filter_samples{{"pcss.filter_samples", "PCSS filter taps", ParamKind::Int, 8.0, 2.0, 16.0,
    "Taps per side of PCSS's variable-width PCF (each a hardware 2 x 2 comparison), spread over the "
    "estimated penumbra: fewer taps, visible steps in wide penumbrae.", {}}};
const ChoiceParam pcss_view{{"pcss.view", "PCSS debug view", ParamKind::Choice, 0.0, 0.0, 2.0,
    "What the view shows in place of the shading. blocker distance: the blockers' mean distance above the "
    "point, dark blue (0) to yellow (pcss.view_range); kernel width: the filter's diameter in map texels on a log "
    "scale, log2(1 + texels) / log2(129): dark blue (0), purple (4), orange (16) to yellow (the cap, 128), pure "
    "red where the cap cuts it. Light grey: the search "
    "found no blocker (fully lit); dark grey: the surface faces away from the light. The red channel is "
    "the value's share of its range.",
    {"shadow", "blocker distance", "kernel width"}}};
const FloatParam pcss_view_range{{"pcss.view_range", "PCSS view range", ParamKind::Float, 4.0, 0.05, 100.0,
    "The blocker distance (world units) that pcss.view = blocker distance shows yellow.", {}, kInvalidatesNothing,
    true}};

}  // namespace param

std::vector<ParamSpec> pcf_param_specs() {
  return specs_of(param::pcf_kernel, param::pcf_hardware, param::pcf_match_light, param::pcf_match_distance,
      param::pcss_blocker_samples, param::pcss_filter_samples, param::pcss_view, param::pcss_view_range);
}

namespace param {

const BoolParam point_single_pass{{"point.single_pass", "Cube map in one pass (GS)", ParamKind::Bool, 0.0, 0.0, 1.0,
    "Draw the six faces in one pass, a geometry shader sending each triangle to every face (gl_Layer), "
    "instead of six passes.", {}, kInvalidatesShadowMap}};

}  // namespace param

std::vector<ParamSpec> point_param_specs() {
  return specs_of(param::point_single_pass);
}

namespace param {

const ChoiceParam volume_method{{"volume.method", "Stencil counting", ParamKind::Choice, 0.0, 0.0, 1.0,
    "z-fail (Carmack's reverse) counts the volume faces behind the surface and needs capped volumes; "
    "z-pass counts those in front and breaks when the camera is inside a volume.", {"z-fail", "z-pass"}}};

}  // namespace param

std::vector<ParamSpec> volume_param_specs() {
  return specs_of(param::volume_method);
}

namespace param {

// Screen-space ambient occlusion (renderer/ssao_pass.h, shaders/ssao/): read by its passes as uniforms.
const FloatParam ssao_radius{{"ssao.radius", "AO radius", ParamKind::Float, 0.5, 0.05, 4.0,
    "How far (world units) a surface may be and still occlude: the hemisphere of samples around each point "
    "has this radius, and the AO truth counts occluders within it.", {}, kInvalidatesNothing, true}};
const IntParam ssao_samples{{"ssao.samples", "AO samples", ParamKind::Int, 32.0, 4.0, 64.0,
    "Kernel samples per pixel (the first N of the renderer's 64): fewer, noisier AO.", {}}};
const FloatParam ssao_bias{{"ssao.bias", "AO depth bias", ParamKind::Float, 0.025, 0.0, 0.2,
    "How far (view-space units) the depth buffer's surface must be in front of a sample to occlude it: 0 lets "
    "a flat surface's own depths, rounded, occlude its samples (self-occlusion).", {}}};
const BoolParam ssao_range_check{{"ssao.range_check", "AO range check", ParamKind::Bool, 1.0, 0.0, 1.0,
    "Passed to the occlusion test as range_check: off, a surface far behind a sample (a wall far in front of "
    "the background) occludes it all the same, and dark halos surround the objects.", {}}};
const BoolParam ssao_blur{{"ssao.blur", "AO blur", ParamKind::Bool, 1.0, 0.0, 1.0,
    "Average the AO over 4 x 4 pixels (the noise texture's tile), which removes the noise's pattern.", {}}};
const BoolParam ssao_noise{{"ssao.noise", "AO noise rotation", ParamKind::Bool, 1.0, 0.0, 1.0,
    "Rotate the kernel per pixel by the 4 x 4 noise texture's vectors; off, every pixel uses the same vector "
    "(1, 0, 0) and the few samples show as bands.", {}}};

// The AO pass's method (renderer/ssao_pass.h): lab 17's SSAO or the renderer's own GTAO. Kept out of
// ssao_param_specs() (lab 17's sliders): a lab or the bench declares them.
const ChoiceParam ssao_method{{"ssao.method", "AO method", ParamKind::Choice, 0.0, 0.0, 1.0,
    "ssao: the kernel of samples in the hemisphere (lab 17's ssao_open); gtao: ground-truth-based AO "
    "(Jimenez et al. 2016), the horizons found along screen-space slices and the cosine-weighted visible "
    "arc between them integrated in closed form.", {"ssao", "gtao"}}};
const IntParam ssao_gtao_directions{{"ssao.gtao_directions", "GTAO slices", ParamKind::Int, 4.0, 1.0, 16.0,
    "GTAO's slice directions per pixel, turned and their steps offset per pixel by the 4 x 4 noise when "
    "ssao.noise is on: fewer, noisier AO.", {}}};
const IntParam ssao_gtao_steps{{"ssao.gtao_steps", "GTAO steps", ParamKind::Int, 8.0, 1.0, 32.0,
    "GTAO's depth samples on each side of a slice, spread over the radius projected on the screen.", {}}};

}  // namespace param

std::vector<ParamSpec> ssao_param_specs() {
  return specs_of(param::ssao_radius, param::ssao_samples, param::ssao_bias, param::ssao_range_check, param::ssao_blur,
                  param::ssao_noise);
}

std::vector<ParamSpec> ao_method_param_specs() {
  return specs_of(param::ssao_method, param::ssao_gtao_directions, param::ssao_gtao_steps);
}

namespace {
std::vector<ParamSpec> all_technique_specs() {
  std::vector<ParamSpec> all;
  for (auto group : {light_param_specs(), pcf_param_specs(), point_param_specs(), volume_param_specs(),
                     ssao_param_specs(), ao_method_param_specs()})
    all.insert(all.end(), group.begin(), group.end());
  return all;
}
// The tables the per-frame lookups of a default read: built once, so a frame allocates nothing.
const std::vector<ParamSpec>& technique_table() {
  static const std::vector<ParamSpec> all = all_technique_specs();
  return all;
}
const std::vector<ParamSpec>& vsm_table() {
  static const std::vector<ParamSpec> all = vsm_param_specs();
  return all;
}
}  // namespace

std::vector<ParamSpec> technique_param_specs(const std::vector<std::string>& keys) {
  std::vector<ParamSpec> out;
  for (const auto& key : keys) out.push_back(spec_in(technique_table(), key, "technique"));
  return out;
}

LightType light_type(const ParamSet& params) {
  const std::string& type = params.get(param::light_type);
  return type == "spot" ? LightType::Spot : type == "point" ? LightType::Point : LightType::Directional;
}

const char* light_type_name(LightType type) {
  return type == LightType::Spot ? "spot" : type == LightType::Point ? "point" : "directional";
}

std::vector<ParamSpec> vsm_param_specs(const std::vector<std::string>& keys) {
  std::vector<ParamSpec> out;
  for (const auto& key : keys) out.push_back(spec_in(vsm_table(), key, "vsm"));
  return out;
}

}  // namespace shadowlab
