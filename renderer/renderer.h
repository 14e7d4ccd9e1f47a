// The one renderer, shared by the window and headless runs. A frame is, in order:
//   scene -> light matrix -> shadow pass -> lit pass -> debug views
// A lab switches features and parameters on (shader includes, the light fit, the light type, the shadow
// technique); it never forks this. With the moments technique (variance shadow maps) the shadow pass is
// the moments pass, optionally followed by a separable blur (renderer/moments_pass.h). A point light's
// shadow pass renders a cube map of distances (renderer/cube_shadow_pass.h). With shadow volumes there
// is no shadow map: the frame is ambient pass -> stencil pass -> additive lit pass
// (renderer/shadow_volume_pass.h).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/gl_objects.h"
#include "renderer/gpu_mesh.h"
#include "renderer/light.h"
#include "renderer/oracle.h"
#include "renderer/params.h"
#include "renderer/scene.h"
#include "renderer/shader.h"
#include "renderer/technique_params.h"

namespace shadowlab {

using LightFit = std::function<LightView(const Bounds& bounds, const glm::vec3& to_light)>;

// What the shadow pass stores: one depth per texel (depth texture, compared in the lit pass; a cube map
// of distances for a point light) or the first two moments of depth (colour texture, filtered, read
// through Chebyshev's bound). ShadowVolumes has no shadow map: stencil shadow volumes from adjacency.
enum class ShadowTechnique { Depth, Moments, ShadowVolumes };

class MomentsPass;
class CubeShadowPass;
class ShadowVolumePass;
struct MomentsTargetInfo;
struct VolumeMeshReport;

// What a lab switches on.
struct LabHooks {
  // Virtual include name -> file, e.g. "lab/bias.glsl" -> "labs/01_bias/exercise.glsl". Names not given
  // fall back to the renderer's defaults in shaders/ (see Renderer::default_includes()).
  std::map<std::string, std::string> includes;
  // Which of those files are a student's, and what they may include (see IncludeRules).
  IncludeRules include_rules;
  LightFit light_fit;  // empty: fit_light_ortho
  // Front-, back- or no culling in the shadow pass, when a lab's exercise decides it (else the parameter).
  std::function<int()> shadow_cull_override;
  // Moments: the vsm.* parameters apply (see renderer/vsm_params.h), "lab/visibility.glsl" defaults to
  // shaders/vsm/visibility.glsl, and "lab/moments.glsl", "lab/chebyshev.glsl", "lab/blur.glsl" apply.
  ShadowTechnique technique = ShadowTechnique::Depth;
  // A lab may pin the light type (the spot and point light labs); unset, the light.type parameter
  // decides (directional where a lab does not declare it). Spot and point lights stand at
  // light.position_*; a spot aims at the scene's centre with the half-angle light.cone_deg.
  std::optional<LightType> light;
  // ShadowVolumes: "lab/volume.glsl" (what a triangle emits) defaults to shaders/volume/volume.glsl, and
  // the volume.* parameters apply (renderer/technique_params.h).
};

struct PassTiming {
  std::string name;
  double gpu_ms = 0.0;      // the pass's cost: its timer query, or its wall time where that is the truth
  bool wall_clock = false;  // gpu_ms is the glFinish-bracketed wall time (see timed() in renderer.cpp)
  double wall_ms = 0.0;     // the glFinish-bracketed wall time around the pass, always measured
};

struct FrameStats {
  std::vector<PassTiming> passes;  // this frame's passes, in order, with GPU time (GL_TIME_ELAPSED)
  double cpu_ms = 0.0;  // wall time of render(), passes included (each is finished before the next)
  // Counters over the renderer's lifetime, so tests can see what was skipped.
  long frames = 0;
  long shadow_passes = 0;   // depth or moments passes
  long moments_passes = 0;  // of which moments passes
  long blur_passes = 0;     // blur passes, one per direction (X and Y: two per blurred shadow map; brute2d: one)
  long cube_faces = 0;      // cube-map faces rendered for point lights (six per shadow pass)
  long stencil_passes = 0;  // shadow-volume stencil passes
  long draws = 0;
  // Shadow casters not drawn into a shadow map (or cube face) because their bounds lie outside the
  // light's volume: they could not have written a texel.
  long casters_culled = 0;
  // Fragments that passed the depth test in the shadow passes (GL_SAMPLES_PASSED; a texel written twice
  // counts twice), plus every texel a blur pass wrote.
  long shadow_texels_written = 0;
  // With RG16F moments: the share of covered texels whose variance came out negative (float16
  // cancellation), measured after each moments update (a read-back, done only for RG16F); -1 otherwise.
  // The panel warns from it.
  double moments_negative_variance = -1.0;
  // What the panel shows when precision ran out (empty when it did not): from 1 % of texels with a
  // negative variance, a warning; from 50 %, the shadows on screen are wrong.
  std::string precision_warning() const;
  nlohmann::json to_json() const;
};

struct FrameRequest {
  OrbitCamera camera;
  int width = 1280;
  int height = 720;
  bool gbuffer = false;  // also write visibility, world positions and normals (for the oracle)
};

class Renderer {
 public:
  Renderer();  // needs a current GL 3.3+ core context
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void set_scene(const Scene& scene);
  const Scene& scene() const { return scene_; }
  // Rebuilds programs with the lab's includes; returns false and keeps the old programs on error.
  bool set_lab(const LabHooks& hooks);
  // Recompiles programs whose files changed on disk (live reload). Returns true when one was swapped.
  bool poll_shader_files();
  // The last shader error, "file:line: message" with the line quoted; empty when all programs built.
  std::string shader_error() const;
  // The compilers' warnings for the current programs, in the same form (empty when there are none).
  std::string shader_warnings() const;

  const FrameStats& render(const ParamSet& params, const FrameRequest& request);
  // Makes the next frame re-run the shadow (moments, blur) passes even if nothing they read changed:
  // for benchmarks that time whole frames.
  void invalidate_shadow_map() { shadow_state_.clear(); }
  // Copies the last frame onto another framebuffer (0: the window), scaled to its size.
  void present(GLuint framebuffer, int width, int height) const;

  // Read-backs of the last frame. Colour is RGBA8 top row first (PNG order); the others are bottom row
  // first (GL order), the layout GBuffer and Truth use.
  std::vector<std::uint8_t> read_color() const;
  std::vector<float> read_visibility() const;
  GBuffer read_gbuffer() const;
  // The shadow map's depths, bottom row first, and its side length (with the moments technique: the
  // moments pass's depth renderbuffer).
  std::vector<float> read_shadow_depth(int* size) const;
  // The moments texture as (E[z], E[z^2]) pairs, bottom row first (after the blur, if one ran); throws
  // unless the lab uses the moments technique.
  std::vector<float> read_moments(int* size) const;
  // The moments targets' format, filtering and attachments as GL reports them.
  MomentsTargetInfo moments_targets() const;
  // The shadow map as a picture (what the debug quad shows), RGBA8 top row first. A point light's six
  // distance faces in a 3 x 3 grid; with shadow volumes (no map) a 16 x 16 grey placeholder.
  std::vector<std::uint8_t> shadow_map_image(int* size) const;

  const LightView& light_view() const { return light_view_; }
  int shadow_map_size() const;  // texels per side of the current shadow (or moments) map
  glm::vec3 to_light() const { return to_light_; }
  glm::mat4 camera_view() const { return camera_view_; }
  glm::mat4 camera_projection() const { return camera_projection_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const FrameStats& stats() const { return stats_; }

  // The light of the last frame. For spot and point lights to_light() points from the scene's centre
  // toward the light (for display); the lit pass uses the position.
  LightType light_type() const { return light_type_; }
  glm::vec3 light_position() const { return light_position_; }
  glm::vec3 spot_direction() const { return spot_direction_; }
  float spot_cone_deg() const { return spot_cone_deg_; }
  const CubeLightViews& cube_views() const { return cube_views_; }
  // The shadow volumes' adjacency report per shadow-casting mesh (empty unless the volume pass exists).
  std::vector<VolumeMeshReport> volume_report() const;
  // One face of the point light's distance cube, bottom row first; throws unless a point light's shadow
  // map was rendered.
  std::vector<float> read_cube_face(int face, int* size) const;

  static std::map<std::string, std::string> default_includes(ShadowTechnique technique = ShadowTechnique::Depth,
                                                             LightType light = LightType::Directional);

 private:
  struct Targets;
  struct Programs;
  struct LitUniforms;
  void ensure_targets(const ParamSet& params, const FrameRequest& request);
  void shadow_pass(const ParamSet& params);
  void lit_pass(const ParamSet& params, const FrameRequest& request);
  void debug_quad_pass(const ParamSet& params);
  void cube_debug_quads(int side);
  void light_volume_pass();
  void set_lit_uniforms(const ParamSet& params, LitUniforms& u);
  static void resolve_lit_uniforms(ReloadableProgram& program, LitUniforms& u);
  void moments_passes(const ParamSet& params);
  void update_light(const ParamSet& params);
  bool build_programs(const LabHooks& hooks, LightType light);
  void shadow_volume_passes(const ParamSet& params, const FrameRequest& request);
  void draw_scene_pass(const ParamSet& params, const FrameRequest& request, int variant);
  void normals_pass(const ParamSet& params);
  void volumes_wireframe_pass(const ParamSet& params);
  glm::vec4 light_vector4() const;
  ShadowVolumePass& volume_pass();
  void remap_view_pass(const ParamSet& params);
  // Every program the current lab uses (the programs live behind pointers, so this is const).
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) const;

  Scene scene_;
  std::unique_ptr<GpuScene> gpu_scene_;
  std::unique_ptr<Targets> targets_;
  std::unique_ptr<Programs> programs_;
  std::unique_ptr<MomentsPass> moments_;  // only while the lab uses the moments technique
  std::unique_ptr<CubeShadowPass> cube_;  // only while a point light casts shadow-map shadows
  std::unique_ptr<ShadowVolumePass> volumes_;  // only with shadow volumes or their wireframe view
  bool volumes_scene_stale_ = true;             // the volume pass's adjacency is for another scene
  GlSampler compare_sampler_;  // GL_COMPARE_REF_TO_TEXTURE, made when a lit program reads a sampler2DShadow
  LabHooks hooks_;
  GlVertexArray empty_vao_;  // core profile needs a VAO bound even for attribute-less full-screen draws
  GlVertexArray lines_vao_;  // the light volume's 12 edges, made on first use
  GlBuffer lines_vbo_;
  GlQuery timer_;
  GlQuery samples_;  // GL_SAMPLES_PASSED around the shadow passes' draws: FrameStats::shadow_texels_written
  // A software rasteriser (llvmpipe) runs the "GPU" work on the CPU: its glFinish-bracketed wall time is
  // the pass's true cost, and its timer queries under-report some passes (see timed()).
  bool software_rasterizer_ = false;

  LightView light_view_;
  glm::vec3 to_light_{0, 1, 0};
  LightType light_type_ = LightType::Directional;
  LightType programs_light_ = LightType::Directional;  // the light type the lit programs were built for
  glm::vec3 light_position_{0.0f}, spot_direction_{0, -1, 0};
  float spot_cone_deg_ = 45.0f;
  CubeLightViews cube_views_;
  glm::mat4 camera_view_{1.0f}, camera_projection_{1.0f};
  int width_ = 0, height_ = 0;
  FrameStats stats_;
  std::string shadow_state_;  // what the current shadow map was rendered for; skip the pass if unchanged
};

}  // namespace shadowlab
