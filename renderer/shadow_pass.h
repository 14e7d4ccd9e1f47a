// A shadow technique is a pass. It owns its render targets and programs; the renderer chooses it once
// per feature set and light type (renderer/shadow_passes.cpp), and a frame runs it in the data flow's
// order:
//
//   1. ensure_targets    allocate what the parameters ask for
//   2. draw_map          the shadow map from the light, only when one of its inputs changed (the
//                        renderer decides: the parameters declared kInvalidatesShadowMap, the light,
//                        the scene, the targets, the pass's program generations)
//      draw_view_passes  what the camera's view needs before the lit pass (shadow volumes' stencil),
//                        after the lit draw the pass's shape asks for first (Shape::lit_first)
//   3. lit_bind          what the lit pass reads: textures and the technique's own uniforms
//   4. lit_view, draw_debug_quads   the false-colour view the technique asks the lit pass for, and its
//                        map in the corner
//
// A pass never draws the lit pass itself: it says which lit variants it wants and when (its shape, its
// lit_view), and the renderer draws them. A new technique is a class implementing this and one line in
// shadow_passes.cpp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/cascades.h"
#include "renderer/debug_annotations.h"
#include "core/frame_light.h"
#include "renderer/frame_stats.h"
#include "renderer/gpu_mesh.h"
#include "renderer/pass_timer.h"
#include "renderer/shader.h"
#include "renderer/gl_host_code.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

// Virtual include name -> file, e.g. "lab/visibility.glsl" -> "shaders/shadow/hard.glsl".
using IncludeMap = std::map<std::string, std::filesystem::path>;

// At most this many shadowed lights beside the frame's own (Features::lights): the lit shader unrolls its
// loop over them (GLSL 3.30 indexes a sampler array with constants only).
constexpr int kMaxShadowedLights = 4;

// Uniform locations of a lit program, resolved once per program generation. A program lacks the ones
// its shadow test does not read (-1: setting them is a no-op).
struct LitUniforms {
  int generation = -1;
  Uniform view_proj, light_tex_matrix, to_light, bias_constant, bias_slope, texel_depth, ambient, shadow_map;
  Uniform light_position, spot_direction, spot_cos_cone, light_near, light_far, texel_angle;
  Uniform light_view_proj;  // without the bias matrix: for a shadow test that applies it itself
  Uniform base_color, alpha_cutoff;  // the material variant's (MATERIAL_TEXTURE)
  struct ShadowedLights {  // the SHADOWED_LIGHTS variant's (shaders/shadow/shadowed_lights.glsl), per entry
    struct Entry {
      Uniform map, tex_matrix, position, direction, cos_cone, near, far, texel_angle, bias_slope, intensity;
    } entry[kMaxShadowedLights];
    Uniform sun_intensity;  // the frame light's weight beside them
  } lights;
};

// What a technique sets on one lit program (ShadowPass::lit_bind): made once per program generation, where
// it looks up the technique's own uniforms (none of which LitUniforms holds), then called every lit draw.
using LitBind = std::function<void(const ParamSet&)>;

// What the lit pass reads besides its own uniforms and the lights (PassContext::lights: each light binds its
// own map), handed to it with the frame (PassContext::lit_inputs) by the renderer: the lit pass knows no
// shadow test by itself. LitConstants
// (renderer/shadow_test.h), the uniforms a lit program may be compiled with as constants, are what a
// technique's few settings decide per pixel (loop counts, branches), so that the lit pass runs no dead
// branch and no uniform-bounded loop for what a lab uses: the pass's (ShadowPass::lit_constants) and
// the selected test's (ShadowTest::constants), which the renderer collects each frame before the lit
// pass draws.
struct LitInputs {
  const ShadowTest* test = nullptr;  // the shadow test whose own uniforms are set (null: none)
  int matched_radius = -1;           // ShadowTestFrame::matched_radius
};

// The define Features::own_shadow_coords (renderer/renderer.h) compiles the lit pass's and the probes'
// programs with: the lab's shadow test maps world space into the shadow map itself.
inline constexpr const char* kOwnShadowCoordsDefine = "OWN_SHADOW_COORDS";

// A texture a lab's material reads in the lit pass (Features::material_textures): RGBA8 texels, row 0 at
// v = 0.
struct MaterialTexture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width x height x 4
};

// The lit pass's program variants (the same scene, shader and uniforms; defines differ).
enum class LitVariant {
  Lit,             // ambient + Lambert scaled by the shadow test's visibility
  VolumeAmbient,   // shadow volumes: ambient only, writing depth (and the G-buffer)
  VolumeAdditive,  // shadow volumes: the light's share, added where the stencil counted no volume
  Overlay,         // the technique's false-colour view over the lit picture (Shape::overlay: its shader)
};

// A technique's false-colour view (the Overlay variant): the scene again through the lit pass's vertex
// shader with the technique's own fragment shader, blended over the lit picture where the depth is equal,
// never into the G-buffer (e.g. the moments' light-bleeding remap, the cascades' tints).
struct LitOverlay {
  const char* fragment = nullptr;  // e.g. "shaders/vsm/remap_view.frag"
  std::vector<std::pair<std::string, std::string>> defines;  // its colours and ranges (what its legend reads)
};

class BillboardPass;
class ShadowPass;

// The texture unit of each shadowed light's map in the lit pass (Features::lights; the techniques use
// the first few, the material from 8 up).
constexpr int kShadowedLightUnits[kMaxShadowedLights] = {7, 15, 14, 13};
class ShadowedLight;

// What a pass reads and records during one frame.
struct PassContext {
  const Scene& scene;
  const GpuScene& gpu_scene;
  const ParamSet& params;
  const FrameLight& light;
  FrameStats& stats;
  PassTimer& timer;
  GLuint empty_vao;  // core profile needs a VAO bound even for attribute-less full-screen draws
  int cull;          // faces the shadow pass skips: 0 none, 1 front, 2 back (a feature's choice or shadow.cull)
  glm::mat4 camera_view{1.0f}, camera_projection{1.0f};
  bool infinite_far_plane = false;  // camera_projection's far plane is at infinity (shadow volumes)
  bool gbuffer = false;             // the lit pass also writes visibility, positions and normals
  // Cascaded shadow maps: the camera the cascades are fitted to (the view's, unless a frame asks for
  // another: FrameRequest::cascade_camera), and a feature's split and fit functions (null or empty: the
  // solution's; pointers into the renderer's features, so that a frame copies no function).
  glm::mat4 cascade_view{1.0f}, cascade_projection{1.0f};
  const CascadeSplitFn* cascade_splits = nullptr;
  const CascadeFitFn* cascade_fit = nullptr;
  // The features' billboards (null: none), which the depth map's pass draws after the casters.
  BillboardPass* billboards = nullptr;
  // Every shadowed light (renderer/shadowed_light.h): entry 0 the frame's own light, whose technique pass
  // binds its map for the lit pass (ShadowPass::lit_bind), then the further lights (Features::lights),
  // entry i's map on kShadowedLightUnits[i - 1]. Set before the first lit draw.
  std::vector<ShadowedLight>* lights = nullptr;
  // The frame's words (debug quads' labels, false-colour legends), filled as the passes draw (null: none).
  DebugAnnotations* annotations = nullptr;
  // What the lit pass binds (every lit draw of the frame reads it; set before the first).
  const LitInputs* lit_inputs = nullptr;

  glm::mat4 camera_view_proj() const { return camera_projection * camera_view; }
  template <typename F>
  void timed(const char* name, F&& pass) {
    timer.time(name, stats, pass);
  }
  // Runs draws, adding the fragments that passed the depth test to stats.shadow_texels_written.
  template <typename F>
  void count_texels(F&& draws) {
    stats.shadow_texels_written += timer.count_samples(stats, draws);
  }
};

// Where the debug quads go: squares `side` high along the bottom right of a width x height view, into
// the bound framebuffer.
struct DebugQuadArea {
  int width = 0, height = 0, side = 0;
  std::string channel;  // view.debug_channel: "all", "depth", "moment 1", "moment 2", "variance"
  GLuint empty_vao = 0;
  std::string light;  // whose map, when not the frame's light ("flashlight"): said before each label
  std::vector<DebugQuadLabel>* labels = nullptr;  // where place() records the quads (null: nowhere)

  // Sets the viewport of one quad and records it with its label: what the quad shows, in words (the
  // label is given here, where the quad is placed, so no quad is drawn without one).
  void place(int x, int y, int quad_width, int quad_height, const std::string& label) const;
};

// The camera view's target: where a pass draws what the view needs before the lit pass.
struct ViewTarget {
  GLuint framebuffer = 0;
  int width = 0, height = 0;
};

// A lit draw a pass asks the renderer for: the lit program's variant and its name among the pass times.
struct LitDraw {
  LitVariant variant = LitVariant::Lit;
  const char* name = "";
};

// A false-colour view a pass asks for after the frame is lit (the variance remap, the cascades): the lit
// draw, and the legend shown over the view.
struct LitView {
  LitDraw draw;
  ColourLegend legend;
};

class ShadowPass {
 public:
  virtual ~ShadowPass() = default;

  // How the technique shapes the frame around it (by default: a map, read by the plain lit pass).
  struct Shape {
    bool has_map = true;        // false: no map to draw, skip or show (shadow volumes)
    bool view_stencil = false;  // the view needs a stencil buffer and a camera far plane at infinity
    LitVariant lit = LitVariant::Lit;  // what the lit pass draws
    // Every variant the pass uses (lit included), built with its includes.
    std::vector<LitVariant> lit_variants{LitVariant::Lit};
    // A lit draw before draw_view_passes (shadow volumes: the ambient pass that lays the depth down).
    std::optional<LitDraw> lit_first{};
    // The Overlay variant's shader, when lit_variants has it.
    std::optional<LitOverlay> overlay{};
  };
  // A constant of the technique, returned by reference: the frame asks for it twice and allocates nothing.
  virtual const Shape& shape() const {
    static const Shape plain{};
    return plain;
  }

  // Points the pass's programs at these includes (the technique's defaults, a feature's on top) under
  // these rules (which files are confined, see IncludeRules) and builds them; false keeps the old
  // programs (the error is in them).
  virtual bool set_includes(const IncludeMap& includes, const IncludeRules& rules) = 0;
  virtual void for_each_program(const std::function<void(ReloadableProgram&)>& f) = 0;
  virtual void set_scene(const Scene&) {}

  // 1. Targets for these parameters; true when they were (re)allocated and the map must be drawn again.
  virtual bool ensure_targets(const ParamSet& params) = 0;
  // The GL host code a lab's exercise may replace (Features::gl_host, renderer/gl_host_code.h); a pass
  // that uses it makes its targets again with new code. Others ignore it.
  virtual void set_host_code(const GlHostCode&) {}
  // What the map depends on besides the parameters, the light, the scene, the targets and the programs,
  // computed every frame before the map is (perhaps) drawn: a change redraws it. Cascades: their
  // matrices, which follow the camera. Filled in place (`out` keeps its capacity from frame to frame).
  virtual void frame_inputs(PassContext&, std::vector<float>& out) { out.clear(); }
  // 2. The shadow map, from the light.
  virtual void draw_map(PassContext&) {}
  virtual void draw_view_passes(PassContext&, const ViewTarget&) {}
  // 3. What the lit pass reads from this technique, on the lit program `program`: a function that binds
  // the pass's textures (its map on unit 0, u_shadow_map) and sets the technique's own uniforms, which it
  // looks up here (the lit pass asks again when the program is rebuilt or the pass changes: serial());
  // it leaves texture unit 0 active. It may hold `this`: the lit pass drops it with the pass.
  virtual LitBind lit_bind(GLuint program) const = 0;
  // Tells passes apart even when one is made where another was freed (the lit pass's cached binds).
  std::uint64_t serial() const { return serial_; }
  // The uniforms among those that the lit program may take as constants, with these parameters' values
  // (the same lit_bind sets; a shadow test's own come from the test, ShadowTest::constants);
  // empty by default. Only parameters declaring kInvalidatesPrograms may decide them. Called every frame: fills `out` in place (no allocation once it holds them).
  virtual void lit_constants(const ParamSet&, LitConstants& out) const { out.clear(); }
  // 4. The technique's own false-colour view for these parameters, drawn by the renderer after the lit
  // pass (none by default), and its map in the corner.
  virtual std::optional<LitView> lit_view(const ParamSet&) const { return std::nullopt; }
  virtual void draw_debug_quads(const DebugQuadArea&) {}

  // A filter matched to the light's size (pcf.match_light, vsm.match_light; FrameLight::
  // matched_filter_radius): the radius in texels the technique uses instead of its parameter's, or -1
  // (the parameter decides). The renderer sets it every frame before ensure_targets.
  void set_matched_radius(int radius) { matched_radius_ = radius; }

  // Texels per side of the map (0 before its targets exist, and for techniques without one).
  virtual int size() const = 0;
  // The depths the map's depth test kept, bottom row first (empty with size 0 when there are none).
  virtual std::vector<float> read_depth(int* size) const;
  // The map as a picture (what the debug quad shows), RGBA8 top row first.
  virtual std::vector<std::uint8_t> image(int* size) const = 0;

 protected:
  int matched_radius_ = -1;

 private:
  static std::uint64_t next_serial();
  const std::uint64_t serial_ = next_serial();
};

// The ALPHA_MASK variant of a shadow pass's program. Alpha-tested (glTF MASK) casters drawn through it
// discard where the view discards (shaders/shadow/alpha_mask.glsl: the base colour's alpha, factor x
// vertex colour x texture, below the material's cutoff), so they cut the same holes into the map as
// into the view and the oracle's truth. It is built on first use, i.e. only for a scene with MASK
// casters: a scene without any never compiles it and draws exactly as before.
class AlphaMaskVariant {
 public:
  using Callback = std::function<void(const GpuScene::Range&)>;
  // `pass_program`: the pass's own program, which the variant follows with ALPHA_MASK defined.
  explicit AlphaMaskVariant(const ProgramDesc& pass_program);
  AlphaMaskVariant(const AlphaMaskVariant&) = delete;  // its callback points at it
  AlphaMaskVariant& operator=(const AlphaMaskVariant&) = delete;
  // The pass's program has new includes (a feature): the variant takes them too, and is rebuilt now if
  // it was built, so that an error in them shows when the feature is switched on. False on a failure.
  bool follow(const ProgramDesc& pass_program);
  // f on the program once built (its generation is then an input of the map; its error is reported).
  void for_each_program(const std::function<void(ReloadableProgram&)>& f);
  // The `masked` argument of GpuScene::draw_casters for one call: null when the scene has no MASK casters
  // (or the variant does not build: they are then drawn solid, and the error is the program's). Before
  // the first masked caster the variant's program is made current and `use` sets the pass's own
  // uniforms on it (through set()); before each masked caster, its texture and cutoff are bound.
  template <typename Use>
  const Callback* prepare(const GpuScene& scene, Use&& use) {
    if (!ready(scene)) return nullptr;  // nothing is made for a scene without MASK casters
    use_ = std::forward<Use>(use);
    return &callback_;
  }
  // A uniform of the variant's program by name (its location looked up once per program build).
  template <typename T>
  void set(const char* name, const T& value) {
    Uniform(location(name)).set(value);
  }
  GLint location(const char* name);

 private:
  // Whether the scene has MASK casters and the program builds (built now the first time).
  bool ready(const GpuScene& scene);

  ProgramDesc desc_;
  ReloadableProgram program_;
  bool built_ = false, current_ = false;
  std::function<void(AlphaMaskVariant&)> use_;
  const GpuScene* scene_ = nullptr;
  Callback callback_;
  int generation_ = -1;
  Uniform base_color_, alpha_cutoff_;
  std::vector<std::pair<std::string, GLint>> locations_;
};

// Faces the shadow pass skips (0 none, 1 front, 2 back): enables or disables GL_CULL_FACE to match.
void set_shadow_culling(int cull);
// Draws the casters into the bound target as the light sees them, with the pass's culling (the caller has
// bound its program and set its light matrix), counting draws and culled casters; culling is off after.
void draw_casters_from_light(PassContext& ctx, const glm::mat4& light_view_proj,
                             const std::function<void(const GpuScene::Range&)>* masked = nullptr);
// A depth map as a picture: the occupied range stretched to full contrast (the cleared background,
// depth 1, stays white), RGBA8 top row first.
std::vector<std::uint8_t> depth_map_image(const std::vector<float>& depth, int size);

}  // namespace shadowlab
