// Variance shadow maps on the GPU: the moments pass and the separable Gaussian blur of the moments,
// with the render targets and programs they own.
//
//   moments pass:  scene from the light -> moments texture A (RG32F/RG16F, linear) + D24 renderbuffer
//   blur X:        A -> ping-pong texture B      (only while the blur radius is > 0)
//   blur Y:        B -> A                        (the lit pass always reads A)
//   or, brute2d:   A -> B with the (2r + 1)^2 kernel, then B copied back into A (glBlitFramebuffer)
//   or, fast at radius <= 4 with compute shaders: both directions A -> B in one dispatch, then A and B
//                  swap names (texture() is always the blurred moments; nothing is copied)
//
// Three blur methods give the same moments (vsm.blur_method; see BlurMethod): the taught separable
// shader ("lab/blur.glsl", shaders/vsm/gaussian_blur.glsl by default), the renderer's fast separable
// blur (a compute shader, shaders/vsm/fast_blur.comp, fused into one dispatch for small radii by
// shaders/vsm/fast_blur2d.comp; without compute shaders a fragment shader with bilinear taps,
// shaders/vsm/fast_blur.frag) and a brute-force 2D pass to compare them with. The blurs are in
// moments_blur.cpp.
//
// The blur writes back into A, so A holds blurred moments afterwards: a change of the blur settings
// redraws the moments too (4-14 ms) rather than keeping a third full-size texture for raw moments.
// The renderer creates this pass only while a feature switches the moments technique on, so the
// depth-map techniques allocate none of it; the ping-pong texture exists only while a blur runs.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "renderer/shadow_pass.h"

namespace shadowlab {

// What GL reports about the targets, queried each time (so checks test GL, not our bookkeeping).
struct MomentsTargetInfo {
  int size = 0;
  GLint internal_format = 0;  // GL_RG32F or GL_RG16F
  GLint min_filter = 0, mag_filter = 0, wrap_s = 0, wrap_t = 0;
  GLint color_attachment_type = 0;  // GL_TEXTURE on COLOR_ATTACHMENT0
  GLint depth_attachment_type = 0;  // GL_RENDERBUFFER on DEPTH_ATTACHMENT
  GLint depth_internal_format = 0;  // the renderbuffer's: GL_DEPTH_COMPONENT24
  bool blur_target = false;         // the ping-pong texture is allocated
};

// The clear value of the moments texture: depth 1 (the far plane) and its square, so texels nothing
// was drawn into read as "nothing in front of anything" and light every point.
inline constexpr float kMomentsClear[4] = {1.0f, 1.0f, 0.0f, 0.0f};

// Exponential variance shadow maps (EVSM, Lauritzen & McCool 2008) reuse this pass, its targets and its
// blur: the moments are of two warped depths, w+ = exp(c+ z) and w- = -exp(-c- z), four moments in the
// format's RGBA variant (RGBA32F for vsm.format RG32F, RGBA16F for RG16F; vsm.warp, vsm.evsm_exponent,
// vsm.evsm_negative_exponent; the shaders are lab 13's). Each exponent is clamped for the format so that
// exp(2c+), the cleared background's second positive moment, and the slope term (at most w^2 more) stay
// finite, 2 exp(2c) <= the format's largest value; the same limit holds c- (exp(-2c-) at the far plane).
inline constexpr float kEvsmMaxExponentRG32F = 42.0f;  // 2 e^84 = 6e36 < 3.4e38
inline constexpr float kEvsmMaxExponentRG16F = 5.0f;   // 2 e^10 = 44053 < 65504
// The exponents the moments are warped with under these parameters, (c+, c-): (0, 0) without the warp
// (plain VSM, two moments), else vsm.evsm_exponent and vsm.evsm_negative_exponent clamped to the format's
// limit above.
glm::vec2 evsm_exponents(const ParamSet& params);
// c+ alone (evsm_exponents(params).x).
float evsm_exponent(const ParamSet& params);
// The clear value of the moments texture for the exponents from evsm_exponents(): kMomentsClear at c+ = 0,
// else the warped far plane's moments (exp(c+), exp(2c+), -exp(-c-), exp(-2c-)).
std::array<float, 4> moments_clear(float warp_exponent, float negative_exponent = 0.0f);

// How the moments are blurred (the vsm.blur_method choices, in order).
enum class BlurMethod {
  Separable,  // the taught shader: "lab/blur.glsl", 2r + 1 texelFetch and exp() per tap, X then Y
  Fast,       // the same separable Gaussian, optimised (shaders/vsm/fast_blur.comp or fast_blur.frag)
  Brute2D,    // one pass of (2r + 1)^2 taps (the 1D weights' outer product) and a copy back into A
};
// "separable", "fast", "brute2d"; throws std::invalid_argument for anything else.
BlurMethod blur_method_from_name(const std::string& name);
const char* blur_method_name(BlurMethod method);

// The 1D Gaussian weights exp(-i^2 / (2 sigma^2)) for i = 0..radius, divided by their sum over
// i = -radius..radius (so the kernel sums to 1); computed in double.
std::vector<double> gaussian_weights(int radius, double sigma);
// The reference blur: the separable Gaussian in double precision, X then Y, clamped to
// the edge, over (E[z], E[z^2]) pairs of an n x n map as read_moments() returns them.
std::vector<double> cpu_gaussian_blur(const std::vector<float>& rg, int n, int radius, double sigma);

class MomentsPass final : public ShadowPass {
 public:
  MomentsPass();
  static std::map<std::string, std::string> default_includes(LightType light);

  // The shadow technique: the vsm.* parameters apply (core/vsm_params.h).
  const Shape& shape() const override {
    static const Shape moments{true,
                               false,
                               LitVariant::Lit,
                               {LitVariant::Lit, LitVariant::Overlay},
                               std::nullopt,
                               LitOverlay{"shaders/vsm/remap_view.frag", remap_view_defines()}};
    return moments;
  }
  // Points the programs' virtual includes ("lab/moments.glsl", "lab/blur.glsl") at files and rebuilds
  // them; false (old programs kept) on a compile error.
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules = {}) override;
  // Every program built so far (the fast and brute-force blur programs are built on first use).
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) override;
  // vsm.format, and the ping-pong texture while vsm.blur_radius > 0.
  bool ensure_targets(const ParamSet& params) override;
  void set_host_code(const GlHostCode& code) override;
  void frame_inputs(PassContext& ctx, std::vector<float>& out) override;
  // The moments, then the blur (vsm.blur_radius, vsm.blur_sigma, vsm.blur_method); with RG16F the
  // share of texels whose variance cancelled (FrameStats::moments_negative_variance).
  void draw_map(PassContext& ctx) override;
  // The moments on unit 0, vsm.min_variance and vsm.bleed_delta.
  LitBind lit_bind(GLuint program) const override;
  // vsm.show_remap: tints the pixels whose visibility the light-bleeding remap lowered.
  std::optional<LitView> lit_view(const ParamSet& params) const override;
  // view.debug_channel "all": E[z], E[z^2] and the variance left to right; else that one channel.
  void draw_debug_quads(const DebugQuadArea& area) override;
  int size() const override { return size_; }
  // The depth renderbuffer, bottom row first.
  std::vector<float> read_depth(int* size) const override;
  // The depth renderbuffer as a picture.
  std::vector<std::uint8_t> image(int* size) const override;

  // (Re)allocates the targets for this size and format ("RG32F" or "RG16F"); the ping-pong texture
  // only when `blur` is true, and it is freed again when false. Returns true when anything changed.
  bool ensure_targets(int size, const std::string& format, bool blur);

  // 1. The moments of the nearest surface per texel, from the light. cull: 0 none, 1 front, 2 back.
  void draw_moments(const GpuScene& scene, const glm::mat4& light_view_proj, int cull, bool cull_casters, long& draws,
                    long& culled);
  // The exponents of EVSM's warps (c+ = 0: none, plain VSM) the next draw_moments uses: its clear value and
  // the moments shader's u_warp_exponent and u_warp_negative_exponent. ensure_targets(params) sets them
  // from evsm_exponents(params); with c+ > 0 the targets hold four moments (RGBA).
  void set_warp_exponent(float c, float negative = 0.0f) {
    warp_exponent_ = c;
    negative_exponent_ = negative;
  }
  float warp_exponent() const { return warp_exponent_; }
  // 2. The blur with the taught shader ("lab/blur.glsl"): X (A -> B) then Y (B -> A), run by lab 5's GL
  // solution (run_blur_passes, renderer/blur_passes.h). Needs ensure_targets(..., blur = true). Four
  // moments (EVSM): two draws per pass, the first pair and then the second (the source swizzled so that
  // .rg reads B and A, the target written through B and A only). `around` (optional) runs each pass's
  // draw, e.g. timed: around(pass, draw).
  using PassWrapper = std::function<void(int pass, const std::function<void()>& draw)>;
  void blur(int radius, float sigma, GLuint empty_vao, const PassWrapper& around = {});
  // The same direction with the fast blur: the same output within float rounding. Call it for 0 then
  // 1: at small radii direction 0 does both (fused) and direction 1 swaps A and B.
  void blur_fast(int direction, int radius, float sigma, GLuint empty_vao);
  // How blur_fast runs: compute shaders where the context has them (GL 4.3+), else fragment shaders
  // with bilinear taps. Tests can force the fragment path.
  enum class FastPath { Compute, Fragment };
  FastPath fast_path() const { return fast_path_; }
  void set_fast_path(FastPath path);
  // The whole blur in one (2r + 1)^2 pass, A -> B, then B copied back into A.
  void blur_brute2d(int radius, float sigma, GLuint empty_vao);
  // A debug quad of one channel (0 E[z], 1 E[z^2], 2 variance) into the bound framebuffer's viewport.
  void draw_debug_quad(int channel, GLuint empty_vao);

  GLuint texture() const { return moments_texture_.id(); }
  GLuint framebuffer() const { return moments_fbo_.id(); }
  // Texture A as (E[z], E[z^2]) pairs, bottom row first.
  std::vector<float> read_moments() const;
  // The share of covered texels (E[z] < 1) whose stored moments give a negative variance,
  // E[z^2] - E[z]^2 < 0: float cancellation. 0 for RG32F on every scene measured; RG16F 2.1 % on the
  // default scene, 5.2 % with a 120-unit depth range, 99.98 % at 1200 (tests/test_gl_stress.cpp).
  static double negative_variance_share(const std::vector<float>& moments);
  MomentsTargetInfo query_targets() const;

 private:
  ReloadableProgram moments_, blur_x_, blur_y_, debug_;
  AlphaMaskVariant mask_;  // moments_ with ALPHA_MASK: alpha-tested (MASK) casters
  struct MomentsUniforms {
    int generation = -1;
    Uniform light_view_proj, warp_exponent, negative_exponent;
  } moments_u_;
  // The lit program's u_warp_negative_exponent (not among the shared LitUniforms): looked up again when
  // another program is bound.
  struct BlurUniforms {
    int generation = -1;
    Uniform moments, radius, sigma;
  } blur_x_u_, blur_y_u_;
  struct DebugUniforms {
    int generation = -1;
    Uniform moments, channel, warp_exponent;
  } debug_u_;
  // The fast blur's programs, built on first use per radius (compiled in, the code unrolled): compute
  // shaders per radius and format (the image format is part of the shader), or the fragment fallback.
  struct ComputeBlur {
    GlProgram x, y;
  };
  std::map<std::pair<int, std::string>, ComputeBlur> fast_compute_;
  std::map<std::pair<int, std::string>, GlProgram> fused_compute_;  // small radii: both directions at once
  struct FragmentBlur {
    ReloadableProgram x, y;
  };
  std::map<int, FragmentBlur> fast_fragment_;
  FastPath fast_path_ = FastPath::Fragment;
  ReloadableProgram brute_;  // built on first use
  void blur_fast_compute(int direction, int radius, float sigma);
  void blur_fused_compute(int direction, int radius, float sigma);
  // Runs a blur compute program: samples `source`, stores into the image `target`, then the barrier.
  void dispatch_blur(GLuint program, GLuint source, GLuint target, int radius, float sigma, int groups_x, int groups_y);
  void blur_fast_fragment(int direction, int radius, float sigma, GLuint empty_vao);
  // The blur of draw_map: X then Y, or the brute-force 2D pass, timed and counted.
  void blur_map(PassContext& ctx, int radius, float sigma, BlurMethod method);

  int size_ = 0;
  GlHostCode code_;  // who makes the targets, begins the pass and runs the blur (the renderer, or a student's file)
  float warp_exponent_ = 0.0f, negative_exponent_ = 0.0f;
  std::string format_;
  bool four_moments_ = false;  // RGBA targets (EVSM's two warps)
  GlTexture moments_texture_;  // A
  GlRenderbuffer depth_;       // the depth test while the moments are drawn
  GlFramebuffer moments_fbo_;
  GlTexture blur_texture_;  // B, the ping-pong target
  GlFramebuffer blur_fbo_;
};

}  // namespace shadowlab
