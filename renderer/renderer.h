// The one renderer, shared by the window and headless runs. A frame is, in order:
//   scene -> light -> shadow pass(es) -> lit pass -> debug views
// Features switch shader includes, the light's fit, the light type and the shadow technique on
// (Features); they never fork this. The shadow technique is a pass (renderer/shadow_pass.h) chosen once
// per feature set and light type (renderer/shadow_passes.cpp): the depth map (renderer/depth_map_pass.h),
// a point light's cube of distances (renderer/cube_shadow_pass.h), the moments with their blur
// (renderer/moments_pass.h), or stencil shadow volumes with no map at all
// (renderer/shadow_volume_pass.h). That pass is the frame light's, the first entry of the renderer's
// list of shadowed lights (renderer/shadowed_light.h); the further lights a feature asks for follow it,
// each with its own depth map. The lit pass (renderer/lit_pass.h) reads every light's map through that
// list, and the debug views (renderer/debug_views.h) show them.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/cascades.h"
#include "renderer/debug_annotations.h"
#include "core/frame_light.h"
#include "renderer/frame_stats.h"
#include "renderer/gl_objects.h"
#include "renderer/gpu_mesh.h"
#include "core/light.h"
#include "oracle/oracle.h"
#include "core/params.h"
#include "renderer/pass_timer.h"
#include "renderer/gl_host_code.h"
#include "core/placement.h"
#include "core/scene.h"
#include "core/shadowed_light_spec.h"
#include "renderer/shader.h"
#include "renderer/shadow_pass.h"
#include "renderer/shadow_passes.h"
#include "renderer/shadowed_light.h"
#include "core/technique_params.h"

namespace shadowlab {

class ShadowPass;
class BillboardPass;
struct PassContext;
class LitPass;
class DebugViews;
class SsaoPass;
struct MomentsTargetInfo;
struct VolumeMeshReport;
struct VolumeTriangles;

// The features a frame uses beyond the parameters: shader includes, a light fit, the shadow technique,
// a fixed light type. Whoever sets them (a lab, a benchmark, a test), the renderer sees only these.
struct Features {
  // Virtual include name -> file, e.g. "lab/bias.glsl" -> an exercise's file. Names not given fall back
  // to the shadow technique's defaults in shaders/ (see Renderer::default_includes()).
  std::map<std::string, std::string> includes;
  // Which of those files are a student's, and what they may include (see IncludeRules).
  IncludeRules include_rules;
  LightFit light_fit;  // a directional light's view and projection; empty: fit_light_ortho
  // Front-, back- or no culling in the shadow pass (0, 1, 2), when something other than the shadow.cull
  // parameter alone decides it (e.g. a directive in an included file, unless a parameter says otherwise);
  // called with the frame's parameters.
  std::function<int(const ParamSet&)> shadow_cull_override;
  // What the shadow pass stores. Moments: the vsm.* parameters apply (core/vsm_params.h), and
  // "lab/moments.glsl", "lab/chebyshev.glsl", "lab/blur.glsl" with it. ShadowVolumes: "lab/volume.glsl"
  // (what a triangle emits) and the volume.* parameters (core/technique_params.h).
  ShadowTechnique technique = ShadowTechnique::Depth;
  // A fixed light type; unset, the light.type parameter decides (directional where it is not declared).
  // Spot and point lights stand at light.position_*; a spot aims at the scene's centre with the
  // half-angle light.cone_deg.
  std::optional<LightType> light;
  // Cascaded shadow maps: the split distances and each cascade's light box (empty: the solution's,
  // core/cascades.h).
  CascadeSplitFn cascade_splits;
  CascadeFitFn cascade_fit;
  // The surfaces' material in the lit pass: "lab/material.glsl" (default shaders/material/plain.glsl,
  // the vertex colour) may read textures and parameters. Each texture is bound for the lit pass under
  // its sampler uniform's name (RGBA8 texels, row 0 at v = 0, repeat-wrapped, nearest filtering); each
  // float uniform is set from a parameter every frame; u_floor_height is the scene's lowest y.
  using MaterialTexture = shadowlab::MaterialTexture;  // renderer/shadow_pass.h
  std::map<std::string, MaterialTexture> material_textures;  // sampler uniform -> texels
  std::map<std::string, std::string> material_params;        // float uniform -> parameter key
  // Billboards (renderer/billboards.h): trees standing at these points of the scene's frame, expanded by a
  // geometry shader; the view turns them toward the camera, the depth map's pass draws the quads
  // "lab/billboard.glsl" makes (default shaders/billboard/shadow_quad.glsl: toward the light) with its
  // alpha test. Their size and cutoff are the billboard.* parameters (billboard_param_specs). With the
  // depth-map technique only.
  std::vector<glm::vec3> billboards;
  // Shadowed lights beside the frame's own (at most kMaxShadowedLights), e.g. lab 15's flashlight
  // (core/flashlight.h's flashlight_spec(): a spot on a node circling the scene or on the camera). Each
  // gets a ShadowedLight (renderer/shadowed_light.h) in the renderer's list after the frame light's (entry
  // 0, Renderer::lights()): its own perspective depth map, redrawn only when it,
  // its casters or its map's settings change. The lit pass combines the frame light's term with the first
  // entry's in "lab/combine.glsl" (default shaders/shadow/combine_lights.glsl), then each further entry's
  // with the light so far (shaders/lit.frag). With the techniques that have a map (not shadow volumes);
  // billboards cast no shadow from them.
  std::vector<ShadowedLightSpec> lights;
  // The lab's shadow test maps world space into the shadow map itself, from u_light_view_proj (lab 0's
  // lesson: the bias matrix). Its programs are then compiled with OWN_SHADOW_COORDS
  // (kOwnShadowCoordsDefine): none of what would hand it that mapping is in them, not
  // shaders/shadow/common.glsl's shadow_coords() and outside_shadow_map(), nor lit.vert's interpolated
  // v_light_tex, nor u_light_tex_matrix, which the lit pass then leaves unset (a test that declares it
  // reads zeros). Probes (grading/probe.h) compile the lab's test the same way.
  bool own_shadow_coords = false;
  // The shadow test (renderer/shadow_test.h) by name ("pcf"; empty: none, the technique's default file
  // reads no uniform of its own): its file goes into "lab/visibility.glsl" unless `includes` names
  // another there (a student's version of it), and the lit pass sets its uniforms, no other test's.
  std::string shadow_test;
  // Screen-space ambient occlusion (renderer/ssao_pass.h) after the lit pass: "lab/ssao.glsl" (default
  // shaders/ssao/ssao_core.glsl) and the ssao.* parameters. Off: no SSAO pass exists at all.
  bool ssao = false;
  // The GL host code of the labs' OpenGL exercises (renderer/gl_host_code.h): the renderer's own functions,
  // or, in the window on the student's machine, those of their edited gl_*.cpp (grading/live_cpp.h).
  GlHostCode gl_host;
};


struct FrameRequest {
  OrbitCamera camera;
  int width = 1280;
  int height = 720;
  bool gbuffer = false;  // also write visibility, world positions and normals (for the oracle)
  // Draw the view straight into the window's framebuffer (0, width x height, with depth and stencil)
  // instead of the renderer's own target: no copy (present() is then not needed, read-backs of the
  // view have nothing to read). Not with gbuffer.
  bool to_window = false;
  GLuint window_framebuffer = 0;  // with to_window: the framebuffer that stands for the window (0: its own)
  // Cascaded shadow maps: fit the cascades to this camera instead of the view's (a debug view freezing the
  // cascades while the view moves; lab 12's check moves this camera under a still view).
  std::optional<OrbitCamera> cascade_camera;
};

// The scene a frame draws from a scene as given: with the ground plane (with_ground) when add_ground,
// and BLEND meshes casting no shadow unless blend_casts. Renderer::set_scene and whoever builds an
// oracle for a dropped model use the same function.
Scene frame_scene(const Scene& scene, bool add_ground, bool blend_casts);
// Whether these parameters add a ground plane to this scene (scene.ground on, has_ground false).
bool adds_ground(const Scene& scene, const ParamSet& params);
// The camera for a scene as given: OrbitCamera::framing's three-quarter view of its box; for a scene that
// gets a ground plane (a dropped model), of the model and its shadow on that ground (the box's corners
// carried down along the light's direction from light.azimuth and light.elevation, the shadow's length
// capped at three times the model's height), with the far plane reaching the whole ground.
OrbitCamera frame_scene_camera(const Scene& scene, const ParamSet& params);
Bounds frame_scene_bounds(const Scene& scene, const ParamSet& params);

class Renderer {
 public:
  Renderer();  // needs a current GL 3.3+ core context
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The scene in its own frame. The scene.* parameters place it in the world (core/placement.h);
  // the GPU gets it in the local frame, converted in double whenever the placement changes.
  // The scene drawn is the one given plus what the parameters add: a ground plane when scene.ground is on
  // and the scene has none of its own (has_ground, core/scene.h), and BLEND meshes as casters or not
  // (scene.blend_casts); scene() is that scene (the oracle's), source_scene() the one given.
  void set_scene(const Scene& scene);
  const Scene& scene() const { return scene_; }
  const Scene& source_scene() const { return source_; }
  bool ground_added() const { return ground_added_; }
  // The last frame's placement, and the scene as the GPU has it (positions relative to the local origin).
  const Placement& placement() const { return placement_; }
  const Scene& local_scene() const { return local_scene_; }
  // Switches to these features: rebuilds the programs with their includes (and the shadow pass, when
  // the technique or light type changes); returns false and keeps the old features on error.
  bool set_features(const Features& features);
  // Recompiles programs whose files changed on disk (live reload). Returns true when one was swapped.
  bool poll_shader_files();
  // The last shader error, "file:line: message" with the line quoted; empty when all programs built.
  std::string shader_error() const;
  // The compilers' warnings for the current programs, in the same form (empty when there are none).
  std::string shader_warnings() const;

  const FrameStats& render(const ParamSet& params, const FrameRequest& request);
  // Makes the next frame re-run the shadow (moments, blur) passes even if nothing they read changed:
  // for benchmarks that time whole frames.
  void invalidate_shadow_map();
  // How passes are timed (renderer/pass_timer.h): Exact (the default: benchmarks, headless runs) waits
  // for every pass; the window asks for interactive_timing(timers_work(), pass line shown).
  void set_timing(TimingMode mode);
  TimingMode timing() const;
  bool timers_work() const;  // false on a software rasteriser: its timer queries measure nothing useful
  // On (the default), the lit pass draws with a program compiled for the technique's settings as
  // constants (ShadowPass::lit_constants, ShadowTest::constants: PCF's kernel and comparison); off, with
  // the generic program reading them as uniforms. Both draw the same image (tests compare them).
  void set_lit_constants(bool on);
  // The constants the last frame's lit program was compiled with (empty: the generic program).
  const LitConstants& drawn_lit_constants() const;
  // Copies the last frame onto another framebuffer (0: the window), scaled to its size.
  void present(GLuint framebuffer, int width, int height) const;

  // Read-backs of the last frame. Colour is RGBA8 top row first (PNG order); the others are bottom row
  // first (GL order), the layout GBuffer and Truth use. The G-buffer's positions are in the scene's own
  // frame (the oracle's): the GPU's local positions converted back in double.
  std::vector<std::uint8_t> read_color() const;
  std::vector<float> read_visibility() const;
  GBuffer read_gbuffer() const;
  // The SSAO pass's AO of the last frame (1 open, 0 occluded), bottom row first: blurred (when ssao.blur
  // was on) or raw. Throws unless the features switch SSAO on.
  std::vector<float> read_ao(bool blurred = true) const;
  // The shadow map's depths, bottom row first, and its side length (with the moments technique: the
  // moments pass's depth renderbuffer; empty with size 0 for a cube map or shadow volumes).
  std::vector<float> read_shadow_depth(int* size) const;
  // The moments texture as (E[z], E[z^2]) pairs, bottom row first (after the blur, if one ran); throws
  // unless the moments technique is on.
  std::vector<float> read_moments(int* size) const;
  // The current technique's pass (the frame light's), for what only it can read back.
  const ShadowPass* shadow_pass() const { return lights_.front().has_pass() ? &lights_.front().pass() : nullptr; }
  // The moments targets' format, filtering and attachments as GL reports them.
  MomentsTargetInfo moments_targets() const;
  // The shadow map as a picture (what the debug quad shows), RGBA8 top row first. A point light's six
  // distance faces in a 3 x 3 grid; with shadow volumes (no map) a 16 x 16 grey placeholder.
  std::vector<std::uint8_t> shadow_map_image(int* size) const;

  // The matrices below are the ones the GPU uses: in the local frame (world - placement().origin()).
  const LightView& light_view() const { return light().view; }
  int shadow_map_size() const;  // texels per side of the current shadow (or moments) map
  glm::vec3 to_light() const { return light().to_light; }
  glm::mat4 camera_view() const { return camera_view_; }
  glm::mat4 camera_projection() const { return camera_projection_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const FrameStats& stats() const { return stats_; }
  // The last frame's words over the view: its debug quads' labels and its false-colour views' legends
  // (renderer/debug_annotations.h); the app draws them (app/view_annotations.h).
  const DebugAnnotations& annotations() const { return annotations_; }

  // Every shadowed light of the last frame (renderer/shadowed_light.h): entry 0 the frame's own light
  // (named kFrameLightName), then one per Features::lights spec, in order; each with its light, its map and
  // its map's updates. shadowed_lights() the entries beside the frame light; shadowed_light(name) throws
  // when there is no entry of that name.
  const std::vector<ShadowedLight>& lights() const { return lights_; }
  std::span<const ShadowedLight> shadowed_lights() const { return std::span(lights_).subspan(1); }
  const ShadowedLight& shadowed_light(const std::string& name) const;
  static constexpr const char* kFrameLightName = "sun";

  // The light of the last frame. For spot and point lights to_light() points from the scene's centre
  // toward the light (for display); the lit pass uses the position.
  const FrameLight& light() const { return lights_.front().light(); }
  LightType light_type() const { return light().type; }
  glm::vec3 light_position() const { return light().scene_position; }  // the scene's frame
  glm::vec3 spot_direction() const { return light().spot_direction; }
  float spot_cone_deg() const { return light().spot_cone_deg; }
  // light.size of the last frame in evaluate_soft's units (radians for a directional light, the scene
  // frame's units for a spot or point light's radius); 0 for a hard light.
  float light_size() const { return light().soft_truth_size(); }
  const CubeLightViews& cube_views() const { return light().cube; }
  // The shadow volumes' adjacency report per shadow-casting mesh (empty unless shadow volumes or their
  // wireframe view were drawn).
  std::vector<VolumeMeshReport> volume_report() const;
  // The triangles the shadow volumes emit for the last frame's light (caps: as z-fail draws them), sorted
  // into sides and caps; needs the shadow-volume technique.
  VolumeTriangles count_volume_triangles(bool caps);
  // One face of the point light's distance cube, bottom row first; throws unless a point light's shadow
  // map was rendered.
  std::vector<float> read_cube_face(int face, int* size) const;

  static std::map<std::string, std::string> default_includes(ShadowTechnique technique = ShadowTechnique::Depth,
                                                             LightType light = LightType::Directional);

 private:
  ShadowedLight& frame_light() { return lights_.front(); }
  const ShadowedLight& frame_light() const { return lights_.front(); }
  bool build_programs(const Features& features, LightType light);
  PassContext frame_context(const ParamSet& params, const FrameRequest& request, bool infinite_far_plane);
  // Every program of the current features (the programs live behind pointers, so this is const).
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) const;

  // Converts scene_ to the local frame of placement_ and uploads it.
  void upload_scene();
  // Applies scene.ground and scene.blend_casts to scene_; true when it changed (upload it).
  bool update_scene_options(const ParamSet& params);

  Scene source_;  // as set_scene was given it
  bool source_has_ground_ = true;
  bool ground_added_ = false;
  bool blend_casts_ = true;
  Scene scene_;
  Placement placement_;
  Scene local_scene_;  // scene_ in the local frame of placement_ (what gpu_scene_ and the passes hold)
  std::unique_ptr<GpuScene> gpu_scene_;
  long scene_generation_ = 0;  // bumps with every set_scene
  Features features_;
  // The errors of the last set_features that failed: its programs may belong to a pass that was not kept.
  std::string failed_build_error_;
  LightType programs_light_ = LightType::Directional;  // the light type the programs were built for
  const ShadowPassEntry* shadow_entry_ = nullptr;      // which technique the frame light's pass is
  const ShadowTest* shadow_test_ = nullptr;             // the features' shadow test (null: none selected)
  std::unique_ptr<LitPass> lit_;
  std::unique_ptr<DebugViews> views_;
  std::unique_ptr<BillboardPass> billboards_;  // only while the features have billboards
  std::unique_ptr<SsaoPass> ssao_;              // only while the features switch SSAO on
  // The frame light (always entry 0, its pass the features' technique), then one per Features::lights entry.
  std::vector<ShadowedLight> lights_;
  std::unique_ptr<PassTimer> timer_;
  GlVertexArray empty_vao_;  // core profile needs a VAO bound even for attribute-less full-screen draws

  LitConstants lit_constants_;  // this frame's, filled in place
  glm::mat4 camera_view_{1.0f}, camera_projection_{1.0f};
  int width_ = 0, height_ = 0;
  FrameStats stats_;
  DebugAnnotations annotations_;
};

}  // namespace shadowlab
