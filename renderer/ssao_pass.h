// Screen-space ambient occlusion (Crytek's SSAO, Mittring 2007, with the normal-oriented hemisphere of
// LearnOpenGL's chapter): a technique of the renderer that a lab switches on (Features::ssao), drawn after
// the lit pass and skipped entirely (no targets, no programs) when no feature asks for it. Its passes:
//   1. view_gbuffer  the scene again, writing view-space positions and normals (its own targets)
//   2. ssao          per pixel, ssao_open() of "lab/ssao.glsl" (default shaders/ssao/ssao_core.glsl):
//                    the kernel's hemisphere around the normal, rotated by the 4 x 4 noise texture, each
//                    sample tested against the positions' depths -> the AO buffer (1 open, 0 occluded)
//      or gtao       with ssao.method = gtao, in its place: gtao_open() of "ao/gtao.glsl" (default
//                    shaders/ssao/gtao_core.glsl), horizons along ssao.gtao_directions screen-space slices
//                    of ssao.gtao_steps samples a side -> the same AO buffer
//   3. ssao_blur     the AO averaged over the noise's 4 x 4 tile (ssao.blur)
//   4. ssao_composite the lit picture multiplied by the AO
// With view.debug_quad, three quads along the bottom left: the AO buffer, the noise, the blurred AO.
// Parameters: ssao.* (core/technique_params.h).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl_objects.h"
#include "renderer/shader.h"
#include "renderer/shadow_pass.h"

namespace shadowlab {


// The kernel's size (the most ssao.samples may ask for) and the noise texture's side.
inline constexpr int kSsaoKernelSize = 64;
inline constexpr int kSsaoNoiseSide = 4;

// The kernel the pass hands the shader (u_kernel): points of the unit hemisphere z >= 0 from a fixed seed,
// uniform in its volume; shaders/ssao/ssao.frag's ssao_kernel(i) scales sample i of n by
// lerp(0.1, 1, (i / n)^2), so that most lie near the centre (LearnOpenGL's SSAO).
std::array<glm::vec3, kSsaoKernelSize> ssao_kernel();
// The noise: 16 vectors of the screen plane (z = 0), x and y uniform in [-1, 1], from a fixed
// seed, row by row.
std::array<glm::vec3, kSsaoNoiseSide * kSsaoNoiseSide> ssao_noise();

class SsaoPass {
 public:
  SsaoPass();
  // Builds the programs with these includes ("lab/ssao.glsl": the student's occlusion, unless the
  // default); false keeps the old ones (the error is in them).
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules);
  void for_each_program(const std::function<void(ReloadableProgram&)>& f);
  // Draws passes 1-4 (and the quads) for the frame the lit pass just drew.
  void draw(PassContext& ctx, const ViewTarget& view);
  // The AO of the last frame, bottom row first (GL order): the blurred one when `blurred` and ssao.blur
  // was on, else the raw one; 1 where no surface was drawn.
  std::vector<float> read_open(bool blurred) const;

 private:
  void ensure_targets(int width, int height);
  void debug_quads(PassContext& ctx, const ViewTarget& view);
  void draw_gbuffer(PassContext& ctx);  // pass 1: view-space positions and normals
  void draw_ssao(PassContext& ctx);     // pass 2 with ssao.method = ssao: the student's occlusion
  void draw_blur(PassContext& ctx);     // pass 3: the blur over the noise's tile
  void draw_gtao(PassContext& ctx);  // pass 2 with ssao.method = gtao (renderer/ssao_gtao.cpp)

  ReloadableProgram gbuffer_, ssao_, gtao_, blur_, composite_, quad_;
  struct GbufferUniforms {
    Uniform view, projection;
  };
  struct SsaoUniforms {
    Uniform position, normal, noise, noise_scale, use_noise, projection, view, kernel, samples, radius, bias, range_check;
  };
  struct GtaoUniforms {
    Uniform position, normal, noise, noise_scale, use_noise, projection, directions, steps, radius;
  };
  struct BlurUniforms {
    Uniform open, position;
  };
  struct ImageUniforms {
    Uniform image, is_noise;
  };
  UniformCache<GbufferUniforms> gbuffer_u_;
  UniformCache<SsaoUniforms> ssao_u_;
  UniformCache<GtaoUniforms> gtao_u_;
  UniformCache<BlurUniforms> blur_u_;
  UniformCache<ImageUniforms> composite_u_, quad_u_;
  int width_ = 0, height_ = 0;
  bool blurred_ = false;  // the last frame's ssao.blur
  GlTexture position_, normal_, open_, blurred_open_, noise_;
  GlRenderbuffer depth_;
  GlFramebuffer gbuffer_fbo_, open_fbo_, blurred_fbo_;
  std::array<glm::vec3, kSsaoKernelSize> kernel_;
};

}  // namespace shadowlab
