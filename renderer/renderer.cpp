#include "renderer/renderer.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/cube_shadow_pass.h"
#include "renderer/image_io.h"
#include "renderer/moments_pass.h"
#include "renderer/shadow_volume_pass.h"
#include "renderer/vsm_params.h"

namespace shadowlab {

nlohmann::json FrameStats::to_json() const {
  nlohmann::json passes_json = nlohmann::json::object();
  nlohmann::json wall_clock = nlohmann::json::array();
  for (const auto& p : passes) {
    passes_json[p.name] = p.gpu_ms;
    if (p.wall_clock) wall_clock.push_back(p.name);
  }
  return {{"gpu_ms", passes_json}, {"gpu_ms_from_wall_clock", wall_clock}, {"cpu_ms", cpu_ms}, {"frames", frames}, {"shadow_passes", shadow_passes},
          {"moments_passes", moments_passes}, {"blur_passes", blur_passes}, {"cube_faces", cube_faces},
          {"stencil_passes", stencil_passes}, {"draws", draws}, {"casters_culled", casters_culled},
          {"shadow_texels_written", shadow_texels_written}, {"moments_negative_variance", moments_negative_variance}};
}

std::string FrameStats::precision_warning() const {
  if (moments_negative_variance < 0.01) return {};
  char text[320];
  if (moments_negative_variance >= 0.5) {
    std::snprintf(text, sizeof text,
                  "RG16F has run out of precision: %.0f %% of the shadow map's texels store a negative variance "
                  "(float16 cancellation over this light's depth range), so the shadows shown are wrong. Use RG32F.",
                  100.0 * moments_negative_variance);
  } else {
    std::snprintf(text, sizeof text,
                  "RG16F: %.1f %% of the shadow map's texels lost their variance to float16 cancellation; Chebyshev "
                  "clamps them to the minimum variance. RG32F stores them exactly.",
                  100.0 * moments_negative_variance);
  }
  return text;
}

std::map<std::string, std::string> Renderer::default_includes(ShadowTechnique technique, LightType light) {
  std::map<std::string, std::string> includes = {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
                                                 {"lab/visibility.glsl", "shaders/shadow/hard.glsl"}};
  // A perspective map's depth is not linear in distance (spot); a point light's cube stores distances.
  if (light == LightType::Spot) includes["lab/visibility.glsl"] = "shaders/shadow/spot.glsl";
  if (light == LightType::Point) includes["lab/visibility.glsl"] = "shaders/shadow/cube.glsl";
  if (technique == ShadowTechnique::ShadowVolumes) {
    includes["lab/visibility.glsl"] = "shaders/volume/stencil_visibility.glsl";
    includes["lab/volume.glsl"] = "shaders/volume/volume.glsl";
  }
  if (technique == ShadowTechnique::Moments) {
    includes["lab/visibility.glsl"] = "shaders/vsm/visibility.glsl";
    includes["lab/moments.glsl"] = "shaders/vsm/moments.glsl";
    includes["lab/chebyshev.glsl"] = "shaders/vsm/chebyshev.glsl";
    includes["lab/blur.glsl"] = "shaders/vsm/gaussian_blur.glsl";
  }
  return includes;
}

struct Renderer::Targets {
  int shadow_size = 0;
  std::string depth_format;
  GlTexture shadow_depth;
  GlFramebuffer shadow_fbo;

  int width = 0, height = 0;
  bool gbuffer = false;
  bool stencil = false;  // DEPTH24_STENCIL8 instead of DEPTH_COMPONENT24: shadow volumes only
  GlTexture color, visibility, position, normal;
  GlRenderbuffer depth;
  GlFramebuffer view_fbo;
};

// Uniform locations of the lit pass (and of the remap view, which draws the same scene), resolved once
// per program generation. The vsm ones are absent (-1, setting them a no-op) in depth programs.
struct Renderer::LitUniforms {
  int generation = -1;
  Uniform view_proj, light_tex_matrix, to_light, bias_constant, bias_slope, texel_depth, ambient, shadow_map;
  Uniform min_variance, bleed_delta;
  Uniform light_position, spot_direction, spot_cos_cone, light_near, light_far, texel_angle, shadow_cube;
  Uniform shadow_map_compare, pcf_radius, pcf_hardware;
  Uniform light_view_proj;  // without the bias matrix: lab 0's exercise applies it itself
};

struct Renderer::Programs {
  ReloadableProgram shadow_depth, lit, lit_gbuffer, debug_quad;
  ReloadableProgram remap_view;  // moments technique only; empty (skipped by all()) otherwise
  // Shadow volumes: the ambient pass's programs (lit and lit_gbuffer are then the additive pass's).
  ReloadableProgram volume_ambient, volume_ambient_gbuffer;
  ReloadableProgram normals;  // the normals debug view (geometry shader)
  ReloadableProgram lines;    // the light volume's wireframe
  ReloadableProgram cube_face;  // a point light's debug quads, one per cube face
  struct Lines {
    int generation = -1;
    Uniform view_proj, color;
  } lines_u;
  struct CubeFace {
    int generation = -1;
    Uniform cube, face, far_plane;
  } cube_face_u;
  struct Normals {
    int generation = -1;
    Uniform view_proj, length;
  } normals_u;
  // Uniform locations, resolved once per program generation.
  struct Shadow {
    int generation = -1;
    Uniform light_view_proj;
  } shadow;
  LitUniforms lit_u, lit_gbuffer_u, remap_view_u, volume_ambient_u, volume_ambient_gbuffer_u;
  struct Quad {
    int generation = -1;
    Uniform depth_map, rect;
  } quad;

  void all(const std::function<void(ReloadableProgram&)>& f) {
    f(shadow_depth);
    f(lit);
    f(lit_gbuffer);
    f(debug_quad);
    f(normals);
    f(lines);
    f(cube_face);
    if (!remap_view.desc().fragment.empty()) f(remap_view);
    if (!volume_ambient.desc().fragment.empty()) f(volume_ambient);
    if (!volume_ambient_gbuffer.desc().fragment.empty()) f(volume_ambient_gbuffer);
  }
};

namespace {

// The lit pass's variants. volume_stage: 0 ordinary, 1 the shadow volumes' ambient pass, 2 their
// additive pass.
ProgramDesc lit_desc(const std::map<std::string, std::string>& includes, const IncludeRules& rules, bool gbuffer,
                     LightType light = LightType::Directional, int volume_stage = 0) {
  ProgramDesc d{"shaders/lit.vert", {}, "shaders/lit.frag", {}, {}, rules};
  if (gbuffer) d.defines.emplace_back("WRITE_GBUFFER", "1");
  if (light == LightType::Spot) d.defines.emplace_back("LIGHT_SPOT", "1");
  if (light == LightType::Point) d.defines.emplace_back("LIGHT_POINT", "1");
  if (volume_stage == 1) d.defines.emplace_back("SHADOW_VOLUME_AMBIENT", "1");
  if (volume_stage == 2) d.defines.emplace_back("SHADOW_VOLUME_ADDITIVE", "1");
  for (const auto& [k, v] : includes) d.includes[k] = v;
  return d;
}

GLenum depth_internal_format(const std::string& name) {
  if (name == "16") return GL_DEPTH_COMPONENT16;
  if (name == "32F") return GL_DEPTH_COMPONENT32F;
  return GL_DEPTH_COMPONENT24;
}

// Times one pass: a GL_TIME_ELAPSED query read at once, and the wall time between two glFinish calls
// around it. On a GPU the query is the figure (a GPU time cannot exceed the wall time around it; if it
// does, the wall time is used and the pass marked). On llvmpipe the "GPU" is the CPU, so the wall time
// is the pass's true cost, and its queries are not: they read 0.01-0.3 ms for passes that draw into the
// framebuffer the previous pass drew into (the stencil shadow volumes' three passes, a lit pass after a
// skipped shadow pass) against 1.1-16.6 ms of wall time, and the first query of a new context reads the
// machine's uptime (3.3e6 ms). There every pass uses the wall time and is marked.
template <typename F>
void timed(GLuint query, const char* name, FrameStats& stats, bool software, F&& pass) {
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, query);
  pass();
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 ns = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
  glFinish();
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double gpu_ms = static_cast<double>(ns) * 1e-6;
  const bool use_wall = software || gpu_ms > wall_ms + 1.0;
  stats.passes.push_back({name, use_wall ? wall_ms : gpu_ms, use_wall, wall_ms});
}

// Runs draws and returns how many fragments passed the depth test (texels written, overdraw included).
template <typename F>
long count_samples(GLuint query, F&& draws) {
  glBeginQuery(GL_SAMPLES_PASSED, query);
  draws();
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samples = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
  return static_cast<long>(samples);
}

bool is_software_rasterizer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer ? renderer : "";
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
         name.find("SwiftShader") != std::string::npos;
}

}  // namespace

Renderer::Renderer()
    : targets_(std::make_unique<Targets>()),
      programs_(std::make_unique<Programs>()),
      empty_vao_(GlVertexArray::create()),
      timer_(GlQuery::create()),
      samples_(GlQuery::create()),
      software_rasterizer_(is_software_rasterizer()) {
  programs_->shadow_depth = ReloadableProgram({"shaders/shadow_depth.vert", {}, "shaders/shadow_depth.frag", {}, {}});
  programs_->debug_quad = ReloadableProgram({"shaders/fullscreen.vert", {}, "shaders/debug_depth.frag", {}, {}});
  programs_->normals =
      ReloadableProgram({"shaders/debug/normals.vert", "shaders/debug/normals.geom", "shaders/debug/normals.frag", {}, {}});
  programs_->lines = ReloadableProgram({"shaders/debug/lines.vert", {}, "shaders/debug/lines.frag", {}, {}});
  programs_->cube_face = ReloadableProgram({"shaders/fullscreen.vert", {}, "shaders/debug/cube_face.frag", {}, {}});
  if (!set_lab({})) throw std::runtime_error("cannot build the renderer's shaders:\n" + shader_error());
}

Renderer::~Renderer() = default;

void Renderer::set_scene(const Scene& scene) {
  scene_ = scene;
  gpu_scene_ = std::make_unique<GpuScene>(scene_);
  volumes_scene_stale_ = true;
  shadow_state_.clear();
}

bool Renderer::set_lab(const LabHooks& hooks) {
  const LightType light = hooks.light ? *hooks.light : programs_light_;
  const bool ok = build_programs(hooks, light);
  shadow_state_.clear();
  stats_.moments_negative_variance = -1.0;
  return ok;
}

bool Renderer::build_programs(const LabHooks& hooks, LightType light) {
  const bool moments = hooks.technique == ShadowTechnique::Moments;
  const bool volumes = hooks.technique == ShadowTechnique::ShadowVolumes;
  auto includes = default_includes(hooks.technique, light);
  for (const auto& [k, v] : hooks.includes) includes[k] = v;
  Programs& p = *programs_;
  p.lit.set_desc(lit_desc(includes, hooks.include_rules, false, light, volumes ? 2 : 0));
  p.lit_gbuffer.set_desc(lit_desc(includes, hooks.include_rules, true, light, volumes ? 2 : 0));
  if (moments) {
    ProgramDesc remap = lit_desc(includes, hooks.include_rules, false);
    remap.fragment = "shaders/vsm/remap_view.frag";
    p.remap_view.set_desc(remap);
  }
  if (volumes) {
    p.volume_ambient.set_desc(lit_desc(includes, hooks.include_rules, false, light, 1));
    p.volume_ambient_gbuffer.set_desc(lit_desc(includes, hooks.include_rules, true, light, 1));
  }
  bool ok = true;
  p.all([&](ReloadableProgram& program) { ok = program.rebuild() && ok; });
  if (moments) {
    if (!moments_) moments_ = std::make_unique<MomentsPass>();
    ok = moments_->set_includes({includes.begin(), includes.end()}, hooks.include_rules) && ok;
  }
  if (volumes) ok = volume_pass().set_includes({includes.begin(), includes.end()}, hooks.include_rules) && ok;
  if (ok) {
    hooks_ = hooks;
    programs_light_ = light;
    if (!moments) {
      moments_.reset();  // a depth lab keeps no moments targets or programs
      p.remap_view = {};
      p.remap_view_u = {};
    }
    if (!volumes) {
      p.volume_ambient = {};
      p.volume_ambient_gbuffer = {};
      p.volume_ambient_u = {};
      p.volume_ambient_gbuffer_u = {};
      volumes_.reset();  // rebuilt on demand by the wireframe view
    }
  }
  return ok;
}

ShadowVolumePass& Renderer::volume_pass() {
  if (!volumes_) {
    volumes_ = std::make_unique<ShadowVolumePass>();
    volumes_scene_stale_ = true;
    std::map<std::string, std::filesystem::path> includes;
    for (const auto& [k, v] : hooks_.includes) includes[k] = v;
    volumes_->set_includes(includes, hooks_.include_rules);
  }
  if (volumes_scene_stale_ && gpu_scene_) {
    volumes_->set_scene(scene_);
    volumes_scene_stale_ = false;
  }
  return *volumes_;
}

std::vector<VolumeMeshReport> Renderer::volume_report() const {
  return volumes_ ? volumes_->report() : std::vector<VolumeMeshReport>{};
}

void Renderer::for_each_program(const std::function<void(ReloadableProgram&)>& f) const {
  programs_->all(f);
  if (moments_) moments_->for_each_program(f);
  if (cube_) cube_->for_each_program(f);
  if (volumes_) volumes_->for_each_program(f);
}

bool Renderer::poll_shader_files() {
  bool swapped = false;
  for_each_program([&](ReloadableProgram& program) { swapped = program.poll_files() || swapped; });
  if (swapped) shadow_state_.clear();
  return swapped;
}

std::string Renderer::shader_error() const {
  std::string out;
  for_each_program([&](ReloadableProgram& program) {
    if (!program.error().empty() && out.find(program.error()) == std::string::npos) out += program.error();
  });
  return out;
}

std::string Renderer::shader_warnings() const {
  std::string out;
  for_each_program([&](ReloadableProgram& program) {
    if (!program.warnings().empty() && out.find(program.warnings()) == std::string::npos) out += program.warnings();
  });
  return out;
}

namespace {
// A vsm.* choice: the lab's value when it declares the key, else the declared default.
std::string vsm_choice(const ParamSet& params, const std::string& key) {
  if (params.find(key)) return params.get_choice(key);
  const ParamSpec spec = vsm_param_specs({key}).at(0);
  return spec.choices.at(static_cast<std::size_t>(spec.default_value));
}
}  // namespace

int Renderer::shadow_map_size() const {
  if (cube_ && light_type_ == LightType::Point) return cube_->size();
  return moments_ && hooks_.technique == ShadowTechnique::Moments ? moments_->size() : targets_->shadow_size;
}

void Renderer::ensure_targets(const ParamSet& params, const FrameRequest& request) {
  Targets& t = *targets_;
  const int size = std::stoi(params.get_choice("shadow.map_size"));
  const std::string& format = params.get_choice("shadow.depth_format");
  const bool volumes = hooks_.technique == ShadowTechnique::ShadowVolumes;
  const bool cube = !volumes && hooks_.technique == ShadowTechnique::Depth && light_type_ == LightType::Point;
  auto free_depth_map = [&] {
    t.shadow_depth = {};
    t.shadow_fbo = {};
    t.shadow_size = 0;
    t.depth_format.clear();
  };
  if (!cube && cube_) cube_.reset();  // the cube maps exist only while a point light casts map shadows
  if (hooks_.technique == ShadowTechnique::Moments) {
    // The moments pass brings its own colour texture and depth renderbuffer: no depth texture.
    free_depth_map();
    const bool blur = static_cast<int>(vsm_param(params, "vsm.blur_radius")) > 0;
    if (moments_->ensure_targets(size, vsm_choice(params, "vsm.format"), blur)) shadow_state_.clear();
  } else if (volumes) {
    free_depth_map();  // shadow volumes need no shadow map, only a stencil buffer (below)
  } else if (cube) {
    free_depth_map();
    if (!cube_) cube_ = std::make_unique<CubeShadowPass>();
    if (cube_->ensure_targets(size)) shadow_state_.clear();
  } else if (size != t.shadow_size || format != t.depth_format) {
    t.shadow_depth = make_texture_2d(depth_internal_format(format), size, size, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NEAREST);
    t.shadow_fbo = GlFramebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, t.shadow_fbo.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, t.shadow_depth.id(), 0);
    glDrawBuffer(GL_NONE);  // depth only: the course's first pass needs no colour buffer
    glReadBuffer(GL_NONE);
    check_framebuffer("shadow map");
    t.shadow_size = size;
    t.depth_format = format;
    shadow_state_.clear();
  }
  if (request.width != t.width || request.height != t.height || request.gbuffer != t.gbuffer || volumes != t.stencil) {
    const int w = request.width, h = request.height;
    t.color = make_texture_2d(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR);
    t.depth = GlRenderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, t.depth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, volumes ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24, w, h);
    t.view_fbo = GlFramebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, volumes ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                              t.depth.id());
    t.stencil = volumes;
    // The G-buffer attachments exist only when a check asks for them.
    t.visibility = {};
    t.position = {};
    t.normal = {};
    if (request.gbuffer) {
      t.visibility = make_texture_2d(GL_R32F, w, h, GL_RED, GL_FLOAT, GL_NEAREST);
      t.position = make_texture_2d(GL_RGBA32F, w, h, GL_RGBA, GL_FLOAT, GL_NEAREST);
      t.normal = make_texture_2d(GL_RGBA32F, w, h, GL_RGBA, GL_FLOAT, GL_NEAREST);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, t.visibility.id(), 0);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, t.position.id(), 0);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, t.normal.id(), 0);
    }
    check_framebuffer("view");
    t.width = w;
    t.height = h;
    t.gbuffer = request.gbuffer;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::update_light(const ParamSet& params) {
  light_type_ = hooks_.light ? *hooks_.light : shadowlab::light_type(params);
  const Bounds bounds = scene_.bounds();
  to_light_ = direction_from_angles(params.get_float("light.azimuth"), params.get_float("light.elevation"));
  if (light_type_ == LightType::Directional) {
    light_view_ = hooks_.light_fit ? hooks_.light_fit(bounds, to_light_) : fit_light_ortho(bounds, to_light_);
    return;
  }
  light_position_ = {technique_param(params, "light.position_x"), technique_param(params, "light.position_y"),
                     technique_param(params, "light.position_z")};
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const glm::vec3 aim = centre - light_position_;
  spot_direction_ = glm::length(aim) > 1e-6f ? glm::normalize(aim) : glm::vec3(0, -1, 0);
  to_light_ = -spot_direction_;
  spot_cone_deg_ = static_cast<float>(technique_param(params, "light.cone_deg"));
  if (light_type_ == LightType::Spot) {
    light_view_ = fit_spot_light(bounds, light_position_, spot_direction_, spot_cone_deg_);
  } else {
    cube_views_ = point_light_views(bounds, light_position_);
    light_view_ = LightView{};
    light_view_.view = cube_views_.view[0];
    light_view_.projection = cube_views_.projection;
  }
}

const FrameStats& Renderer::render(const ParamSet& params, const FrameRequest& request) {
  if (!gpu_scene_) throw std::logic_error("Renderer::render called before set_scene");
  const auto cpu_start = std::chrono::steady_clock::now();
  stats_.passes.clear();
  ++stats_.frames;

  // 1. The light: its type, direction or position from the sliders, its view and projection from the
  // lab's fit (directional), the spot's cone or the point light's six faces.
  update_light(params);
  if (light_type_ != programs_light_) build_programs(hooks_, light_type_);  // on failure the error shows
  ensure_targets(params, request);
  width_ = request.width;
  height_ = request.height;
  camera_view_ = request.camera.view();
  const float aspect = static_cast<float>(request.width) / static_cast<float>(request.height);
  const bool volumes = hooks_.technique == ShadowTechnique::ShadowVolumes;
  // Shadow volumes reach to infinity: the camera's far plane goes there too (third row 0, 0, -1, -2n).
  camera_projection_ = volumes ? glm::infinitePerspective(glm::radians(request.camera.fov_y_deg), aspect,
                                                          request.camera.near_plane)
                               : request.camera.projection(aspect);

  if (volumes) {
    // 2-3. Ambient pass, stencil pass, additive lit pass: no shadow map.
    shadow_volume_passes(params, request);
  } else {
    // 2. Shadow pass, only when what it depends on changed (light, casters, map settings, shaders).
    std::string state(reinterpret_cast<const char*>(&light_view_.view), sizeof(glm::mat4) * 1);
    state.append(reinterpret_cast<const char*>(&light_view_.projection), sizeof(glm::mat4));
    state += params.get_choice("shadow.cull") + (hooks_.shadow_cull_override ? std::to_string(hooks_.shadow_cull_override()) : "");
    state += light_type_name(light_type_);
    state += params.get_bool("shadow.cull_casters") ? " cull-casters" : " all-casters";
    state.append(reinterpret_cast<const char*>(&light_position_), sizeof(glm::vec3));
    const bool point = light_type_ == LightType::Point;
    if (point) state += technique_param(params, "point.single_pass") != 0.0 ? " single" : " six";
    const bool moments = hooks_.technique == ShadowTechnique::Moments;
    if (moments) {
      // The blur overwrites the moments it read (ping-pong back into A), so its settings are inputs of
      // the moments pass too.
      state += "moments " + vsm_choice(params, "vsm.format");
      state += " r" + std::to_string(vsm_param(params, "vsm.blur_radius"));
      state += " s" + std::to_string(vsm_param(params, "vsm.blur_sigma"));
      state += " " + vsm_choice(params, "vsm.blur_method");
    }
    if (state != shadow_state_) {
      if (moments) {
        moments_passes(params);
      } else if (point) {
        const bool single = technique_param(params, "point.single_pass") != 0.0;
        timed(timer_.id(), "cube_shadow", stats_, software_rasterizer_, [&] {
          stats_.shadow_texels_written += count_samples(samples_.id(), [&] {
            cube_->draw(*gpu_scene_, cube_views_, light_position_, single, params.get_bool("shadow.cull_casters"),
                        stats_.draws, stats_.cube_faces, stats_.casters_culled);
          });
        });
      } else {
        timed(timer_.id(), "shadow", stats_, software_rasterizer_,
              [&] { stats_.shadow_texels_written += count_samples(samples_.id(), [&] { shadow_pass(params); }); });
      }
      ++stats_.shadow_passes;
      shadow_state_ = state;
    }

    // 3. Lit pass from the camera, reading the shadow map (or the moments).
    timed(timer_.id(), "lit", stats_, software_rasterizer_, [&] { lit_pass(params, request); });
  }

  // 4. Debug views.
  if (hooks_.technique == ShadowTechnique::Moments && vsm_param(params, "vsm.show_remap") != 0.0)
    timed(timer_.id(), "remap_view", stats_, software_rasterizer_, [&] { remap_view_pass(params); });
  if (params.get_bool("view.normals")) timed(timer_.id(), "normals_view", stats_, software_rasterizer_, [&] { normals_pass(params); });
  if (params.get_bool("view.volumes"))
    timed(timer_.id(), "volumes_view", stats_, software_rasterizer_, [&] { volumes_wireframe_pass(params); });
  if (params.get_bool("view.light_volume") && light_type_ != LightType::Point)
    timed(timer_.id(), "light_volume_view", stats_, software_rasterizer_, [&] { light_volume_pass(); });
  if (!volumes && params.get_bool("view.debug_quad"))  // shadow volumes have no map to show
    timed(timer_.id(), "debug_quad", stats_, software_rasterizer_, [&] { debug_quad_pass(params); });

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  stats_.cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start).count();
  return stats_;
}

glm::vec4 Renderer::light_vector4() const {
  return light_type_ == LightType::Directional ? glm::vec4(to_light_, 0.0f) : glm::vec4(light_position_, 1.0f);
}

void Renderer::shadow_volume_passes(const ParamSet& params, const FrameRequest& request) {
  ShadowVolumePass& volumes = volume_pass();
  const bool z_fail = technique_choice(params, "volume.method") == "z-fail";
  // 2a. The scene with ambient light only: colour, depth (and the G-buffer, visibility 0).
  timed(timer_.id(), "ambient", stats_, software_rasterizer_, [&] { draw_scene_pass(params, request, 1); });
  // 2b. The volumes into the stencil buffer.
  timed(timer_.id(), "volumes", stats_, software_rasterizer_, [&] {
    glBindFramebuffer(GL_FRAMEBUFFER, targets_->view_fbo.id());
    glViewport(0, 0, targets_->width, targets_->height);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    volumes.draw_stencil(camera_projection_ * camera_view_, light_vector4(), z_fail, stats_.draws);
  });
  ++stats_.stencil_passes;
  // 3. The light's share, added where no volume was counted (stencil == 0).
  timed(timer_.id(), "lit", stats_, software_rasterizer_, [&] { draw_scene_pass(params, request, 2); });
  glDisable(GL_STENCIL_TEST);
}

void Renderer::draw_scene_pass(const ParamSet& params, const FrameRequest& request, int stage) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  const bool ambient = stage == 1;
  ReloadableProgram& program =
      ambient ? (request.gbuffer ? p.volume_ambient_gbuffer : p.volume_ambient) : (request.gbuffer ? p.lit_gbuffer : p.lit);
  LitUniforms& u = ambient ? (request.gbuffer ? p.volume_ambient_gbuffer_u : p.volume_ambient_u)
                           : (request.gbuffer ? p.lit_gbuffer_u : p.lit_u);
  if (u.generation != program.generation()) resolve_lit_uniforms(program, u);
  glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
  glViewport(0, 0, t.width, t.height);
  glEnable(GL_DEPTH_TEST);
  if (ambient) {
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    glDrawBuffers(request.gbuffer ? 4 : 1, buffers);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    const float background[] = {0.16f, 0.18f, 0.22f, 1.0f};
    const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, background);
    if (request.gbuffer)
      for (int i = 1; i < 4; ++i) glClearBufferfv(GL_COLOR, i, zero);
    glClear(GL_DEPTH_BUFFER_BIT);
  } else {
    // Colour and visibility only; positions and normals stay as the ambient pass wrote them.
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_NONE, GL_NONE};
    glDrawBuffers(request.gbuffer ? 4 : 1, buffers);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_EQUAL);  // exactly the surfaces the ambient pass kept (lit.vert's gl_Position is invariant)
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }
  glUseProgram(program.id());
  set_lit_uniforms(params, u);
  gpu_scene_->bind();
  for (const auto& range : gpu_scene_->ranges()) {
    gpu_scene_->draw(range);
    ++stats_.draws;
  }
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void Renderer::normals_pass(const ParamSet&) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  if (p.normals_u.generation != p.normals.generation())
    p.normals_u = {p.normals.generation(), Uniform(p.normals.id(), "u_view_proj"), Uniform(p.normals.id(), "u_normal_length")};
  bind_color_target(t.view_fbo.id(), t.width, t.height);  // lines over the picture; the G-buffer stays as drawn
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glUseProgram(p.normals.id());
  p.normals_u.view_proj.set(camera_projection_ * camera_view_);
  // A few percent of the scene's size: long enough to see, short enough not to hide the scene.
  const Bounds b = scene_.bounds();
  p.normals_u.length.set(b.empty() ? 0.1f : 0.03f * glm::length(b.extent()));
  gpu_scene_->bind();
  for (const auto& range : gpu_scene_->ranges()) {
    gpu_scene_->draw(range);
    ++stats_.draws;
  }
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void Renderer::volumes_wireframe_pass(const ParamSet& params) {
  ShadowVolumePass& volumes = volume_pass();
  Targets& t = *targets_;
  bind_color_target(t.view_fbo.id(), t.width, t.height);
  // Lines running to infinity need the infinite far plane, whatever the technique drew with; the depth
  // test against the scene is then only approximate for the other techniques (a different projection).
  glm::mat4 projection = camera_projection_;  // the same field of view, its far plane moved to infinity
  const float near_plane = projection[3][2] / (projection[2][2] - 1.0f);
  projection[2][2] = -1.0f;
  projection[3][2] = -2.0f * near_plane;
  const bool same_projection = hooks_.technique == ShadowTechnique::ShadowVolumes;
  const glm::mat4 view_proj = (same_projection ? camera_projection_ : projection) * camera_view_;
  if (!same_projection) glDisable(GL_DEPTH_TEST);
  const bool caps = technique_choice(params, "volume.method") == "z-fail";
  volumes.draw_wireframe(view_proj, light_vector4(), caps, stats_.draws);
  glEnable(GL_DEPTH_TEST);
}

void Renderer::shadow_pass(const ParamSet& params) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  if (p.shadow.generation != p.shadow_depth.generation()) {
    p.shadow.light_view_proj = Uniform(p.shadow_depth.id(), "u_light_view_proj");
    p.shadow.generation = p.shadow_depth.generation();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, t.shadow_fbo.id());
  glViewport(0, 0, t.shadow_size, t.shadow_size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  const int cull = hooks_.shadow_cull_override ? hooks_.shadow_cull_override()
                                               : static_cast<int>(params.get("shadow.cull"));
  if (cull == 0) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(cull == 1 ? GL_FRONT : GL_BACK);
  }
  glUseProgram(p.shadow_depth.id());
  p.shadow.light_view_proj.set(light_view_.view_projection());
  const glm::mat4 light_view_proj = light_view_.view_projection();
  const auto counts = gpu_scene_->draw_casters(&light_view_proj, 1, params.get_bool("shadow.cull_casters"));
  stats_.draws += counts.drawn;
  stats_.casters_culled += counts.culled;
  glDisable(GL_CULL_FACE);
}

void Renderer::moments_passes(const ParamSet& params) {
  MomentsPass& m = *moments_;
  const int cull =
      hooks_.shadow_cull_override ? hooks_.shadow_cull_override() : static_cast<int>(params.get("shadow.cull"));
  // 2a. The moments (z, z^2 + slope term) of the nearest surface per texel.
  timed(timer_.id(), "moments", stats_, software_rasterizer_,
        [&] {
          stats_.shadow_texels_written += count_samples(samples_.id(), [&] {
            m.draw_moments(*gpu_scene_, light_view_.view_projection(), cull, params.get_bool("shadow.cull_casters"),
                           stats_.draws, stats_.casters_culled);
          });
        });
  ++stats_.moments_passes;
  // 2b. The Gaussian over the moments: X then Y (the taught shader or the fast one), or one 2D pass
  // and its copy back into A (brute2d, timed together as "blur_2d"). Radius 0 runs none of them (and
  // ensure_targets allocated no ping-pong texture).
  const int radius = static_cast<int>(vsm_param(params, "vsm.blur_radius"));
  const auto sigma = static_cast<float>(vsm_param(params, "vsm.blur_sigma"));
  if (radius > 0) {
    const BlurMethod method = blur_method_from_name(vsm_choice(params, "vsm.blur_method"));
    // Every blur writes the whole map once per direction (brute 2D: once, and once more copying back).
    const long map_texels = static_cast<long>(m.size()) * m.size();
    stats_.shadow_texels_written += 2 * map_texels;
    if (method == BlurMethod::Brute2D) {
      timed(timer_.id(), "blur_2d", stats_, software_rasterizer_, [&] { m.blur_brute2d(radius, sigma, empty_vao_.id()); });
      stats_.blur_passes += 1;
    } else {
      const bool fast = method == BlurMethod::Fast;
      for (int direction : {0, 1})
        timed(timer_.id(), direction == 0 ? "blur_x" : "blur_y", stats_, software_rasterizer_, [&] {
          fast ? m.blur_fast(direction, radius, sigma, empty_vao_.id()) : m.blur(direction, radius, sigma, empty_vao_.id());
        });
      stats_.blur_passes += 2;
    }
  }
  // Half floats run out of precision on large depth ranges: measure it so the panel can say so.
  stats_.moments_negative_variance =
      vsm_choice(params, "vsm.format") == "RG16F" ? MomentsPass::negative_variance_share(m.read_moments()) : -1.0;
}

void Renderer::set_lit_uniforms(const ParamSet& params, LitUniforms& u) {
  u.view_proj.set(camera_projection_ * camera_view_);
  u.light_tex_matrix.set(clip_to_texture() * light_view_.view_projection());
  u.light_view_proj.set(light_view_.view_projection());
  u.to_light.set(to_light_);
  u.bias_constant.set(params.get_float("shadow.bias"));
  u.bias_slope.set(params.get_float("shadow.slope_bias"));
  // One shadow-map texel's world size, in the depth units the comparison uses ([0, 1] over the ortho
  // box's depth): a slope-scaled bias in texels multiplies this by tan(angle of incidence).
  const float depth_range = 2.0f / std::abs(light_view_.projection[2][2]);
  u.texel_depth.set(light_view_.world_size.x / static_cast<float>(shadow_map_size()) / depth_range);
  u.ambient.set(params.get_float("view.ambient"));
  // Positional lights: where the light stands, the spot's cone, the fitted planes and a texel's angle.
  u.light_position.set(light_position_);
  u.spot_direction.set(spot_direction_);
  u.spot_cos_cone.set(std::cos(glm::radians(spot_cone_deg_)));
  const int map_size = light_type_ == LightType::Point ? (cube_ ? cube_->size() : 1) : std::max(shadow_map_size(), 1);
  if (light_type_ == LightType::Spot) {
    const glm::mat4& proj = light_view_.projection;  // near and far back from the perspective matrix
    u.light_near.set(proj[3][2] / (proj[2][2] - 1.0f));
    u.light_far.set(proj[3][2] / (proj[2][2] + 1.0f));
    u.texel_angle.set(2.0f * std::tan(glm::radians(spot_cone_deg_)) / static_cast<float>(map_size));
  } else if (light_type_ == LightType::Point) {
    u.texel_angle.set(2.0f / static_cast<float>(map_size));  // a 90-degree face: 2 tan(45 deg) / size
  }
  if (cube_ && light_type_ == LightType::Point) {
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube_->texture());
    u.shadow_cube.set(2);
  }
  if (u.shadow_map_compare.present()) {
    // PCF in hardware: the same depth texture on unit 1 through a sampler that compares (and filters
    // the four comparisons bilinearly); unit 0 keeps reading raw depths.
    if (!compare_sampler_) {
      compare_sampler_ = GlSampler::create();
      glSamplerParameteri(compare_sampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
      glSamplerParameteri(compare_sampler_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
      glSamplerParameteri(compare_sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glSamplerParameteri(compare_sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glSamplerParameteri(compare_sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glSamplerParameteri(compare_sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, targets_->shadow_depth.id());
    glBindSampler(1, compare_sampler_.id());
    u.shadow_map_compare.set(1);
  }
  u.pcf_radius.set(std::stoi(technique_choice(params, "pcf.kernel")) / 2);
  u.pcf_hardware.set(technique_param(params, "pcf.hardware") != 0.0 ? 1 : 0);
  const bool moments = hooks_.technique == ShadowTechnique::Moments;
  if (moments) {
    u.min_variance.set(static_cast<float>(vsm_param(params, "vsm.min_variance")));
    u.bleed_delta.set(static_cast<float>(vsm_param(params, "vsm.bleed_delta")));
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, moments ? moments_->texture() : targets_->shadow_depth.id());
  u.shadow_map.set(0);
}

void Renderer::lit_pass(const ParamSet& params, const FrameRequest& request) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  ReloadableProgram& program = request.gbuffer ? p.lit_gbuffer : p.lit;
  LitUniforms& u = request.gbuffer ? p.lit_gbuffer_u : p.lit_u;
  if (u.generation != program.generation()) resolve_lit_uniforms(program, u);
  glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glDrawBuffers(request.gbuffer ? 4 : 1, buffers);
  glViewport(0, 0, t.width, t.height);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  const float background[] = {0.16f, 0.18f, 0.22f, 1.0f};
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, background);
  if (request.gbuffer)
    for (int i = 1; i < 4; ++i) glClearBufferfv(GL_COLOR, i, zero);  // position.w = 0 marks background
  glClear(GL_DEPTH_BUFFER_BIT);

  glUseProgram(program.id());
  set_lit_uniforms(params, u);
  gpu_scene_->bind();
  for (const auto& range : gpu_scene_->ranges()) {
    gpu_scene_->draw(range);
    ++stats_.draws;
  }
}

void Renderer::resolve_lit_uniforms(ReloadableProgram& program, LitUniforms& u) {
  const GLuint id = program.id();
  u = {program.generation(),
       Uniform(id, "u_view_proj"),
       Uniform(id, "u_light_tex_matrix"),
       Uniform(id, "u_to_light"),
       Uniform(id, "u_bias_constant"),
       Uniform(id, "u_bias_slope"),
       Uniform(id, "u_texel_depth"),
       Uniform(id, "u_ambient"),
       Uniform(id, "u_shadow_map"),
       Uniform(id, "u_min_variance"),
       Uniform(id, "u_bleed_delta"),
       Uniform(id, "u_light_position"),
       Uniform(id, "u_spot_direction"),
       Uniform(id, "u_spot_cos_cone"),
       Uniform(id, "u_light_near"),
       Uniform(id, "u_light_far"),
       Uniform(id, "u_texel_angle"),
       Uniform(id, "u_shadow_cube"),
       Uniform(id, "u_shadow_map_compare"),
       Uniform(id, "u_pcf_radius"),
       Uniform(id, "u_pcf_hardware"),
       Uniform(id, "u_light_view_proj")};
}

void Renderer::remap_view_pass(const ParamSet& params) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  if (p.remap_view_u.generation != p.remap_view.generation()) resolve_lit_uniforms(p.remap_view, p.remap_view_u);
  bind_color_target(t.view_fbo.id(), t.width, t.height);  // a tint over the picture; the G-buffer stays as drawn
  // The same vertices through the same vertex shader give the same depths: LEQUAL keeps exactly the
  // visible surfaces.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(p.remap_view.id());
  set_lit_uniforms(params, p.remap_view_u);
  gpu_scene_->bind();
  for (const auto& range : gpu_scene_->ranges()) {
    gpu_scene_->draw(range);
    ++stats_.draws;
  }
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void Renderer::debug_quad_pass(const ParamSet& params) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  bind_color_target(t.view_fbo.id(), t.width, t.height);  // the quads must not overwrite the G-buffer
  glDisable(GL_DEPTH_TEST);
  // Squares along the bottom right (the panel sits on the left), view.debug_quad_size of the frame height.
  const int side = std::max(8, static_cast<int>(static_cast<float>(t.height) * params.get_float("view.debug_quad_size")));
  const std::string channel = params.get_choice("view.debug_channel");
  if (cube_ && light_type_ == LightType::Point) {
    cube_debug_quads(side);
  } else if (hooks_.technique == ShadowTechnique::Moments) {
    // "all": E[z], E[z^2] and the variance left to right; else the one channel ("depth" is E[z]).
    const int only = channel == "moment 2" ? 1 : channel == "variance" ? 2 : channel == "all" ? -1 : 0;
    const int count = only < 0 ? 3 : 1;
    for (int i = 0; i < count; ++i) {
      glViewport(t.width - (count - i) * (side + 8), 8, side, side);
      moments_->draw_debug_quad(only < 0 ? i : only, empty_vao_.id());
    }
  } else {
    if (p.quad.generation != p.debug_quad.generation()) {
      p.quad = {p.debug_quad.generation(), Uniform(p.debug_quad.id(), "u_depth_map"), Uniform(p.debug_quad.id(), "u_rect")};
    }
    glViewport(t.width - side - 8, 8, side, side);
    glUseProgram(p.debug_quad.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, t.shadow_depth.id());
    p.quad.depth_map.set(0);
    p.quad.rect.set(glm::vec4(0, 0, 1, 1));
    glBindVertexArray(empty_vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glEnable(GL_DEPTH_TEST);
  glViewport(0, 0, t.width, t.height);
}

void Renderer::cube_debug_quads(int side) {
  // The six faces in a 3 x 2 grid, top row +X -X +Y, bottom row -Y +Z -Z, together `side` high.
  Programs& p = *programs_;
  if (p.cube_face_u.generation != p.cube_face.generation()) {
    const GLuint id = p.cube_face.id();
    p.cube_face_u = {p.cube_face.generation(), Uniform(id, "u_cube"), Uniform(id, "u_face"), Uniform(id, "u_far")};
  }
  const Targets& t = *targets_;
  const int cell = side / 2;
  glUseProgram(p.cube_face.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_->texture());
  p.cube_face_u.cube.set(0);
  p.cube_face_u.far_plane.set(std::max(cube_views_.far_plane, 1e-6f));
  glBindVertexArray(empty_vao_.id());
  for (int f = 0; f < 6; ++f) {
    glViewport(t.width - 8 - (3 - f % 3) * (cell + 4), 8 + (f < 3 ? cell + 4 : 0), cell, cell);
    p.cube_face_u.face.set(f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
}

void Renderer::light_volume_pass() {
  // The 12 edges of the shadow map's volume: the clip cube [-1, 1]^3 taken back to world space through
  // the inverse of the light's view-projection (an ortho box or a spot's frustum alike).
  const glm::mat4 to_world = glm::inverse(light_view_.view_projection());
  glm::vec3 corner[8];
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = to_world * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
    corner[i] = glm::vec3(c) / c.w;
  }
  std::vector<glm::vec3> lines;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) lines.insert(lines.end(), {corner[i], corner[i | bit]});
  if (!lines_vao_) {
    lines_vao_ = GlVertexArray::create();
    lines_vbo_ = GlBuffer::create();
    glBindVertexArray(lines_vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, lines_vbo_.id());
    glBufferData(GL_ARRAY_BUFFER, 24 * sizeof(glm::vec3), nullptr, GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  }
  glBindVertexArray(lines_vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, lines_vbo_.id());
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(lines.size() * sizeof(glm::vec3)), lines.data());
  Programs& p = *programs_;
  if (p.lines_u.generation != p.lines.generation())
    p.lines_u = {p.lines.generation(), Uniform(p.lines.id(), "u_view_proj"), Uniform(p.lines.id(), "u_color")};
  Targets& t = *targets_;
  bind_color_target(t.view_fbo.id(), t.width, t.height);
  glDisable(GL_DEPTH_TEST);  // the whole box, also where the scene hides it
  glUseProgram(p.lines.id());
  p.lines_u.view_proj.set(camera_projection_ * camera_view_);
  p.lines_u.color.set(glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
  ++stats_.draws;
  glEnable(GL_DEPTH_TEST);
}

void Renderer::present(GLuint framebuffer, int width, int height) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_->view_fbo.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(0, 0, targets_->width, targets_->height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

namespace {
std::vector<float> read_float_attachment(GLuint fbo, GLenum attachment, int w, int h, GLenum format, int channels) {
  std::vector<float> data(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(channels));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, format, GL_FLOAT, data.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return data;
}
}  // namespace

std::vector<std::uint8_t> Renderer::read_color() const {
  const Targets& t = *targets_;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.view_fbo.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  flip_rows(rgba, t.width, t.height, 4);
  return rgba;
}

std::vector<float> Renderer::read_visibility() const {
  const Targets& t = *targets_;
  if (!t.gbuffer) throw std::logic_error("read_visibility needs a frame rendered with gbuffer = true");
  return read_float_attachment(t.view_fbo.id(), GL_COLOR_ATTACHMENT1, t.width, t.height, GL_RED, 1);
}

GBuffer Renderer::read_gbuffer() const {
  const Targets& t = *targets_;
  if (!t.gbuffer) throw std::logic_error("read_gbuffer needs a frame rendered with gbuffer = true");
  const auto pos = read_float_attachment(t.view_fbo.id(), GL_COLOR_ATTACHMENT2, t.width, t.height, GL_RGBA, 4);
  const auto nrm = read_float_attachment(t.view_fbo.id(), GL_COLOR_ATTACHMENT3, t.width, t.height, GL_RGBA, 4);
  GBuffer g;
  g.width = t.width;
  g.height = t.height;
  const std::size_t n = static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height);
  g.position.resize(n);
  g.normal.resize(n);
  g.covered.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    g.position[i] = {pos[4 * i], pos[4 * i + 1], pos[4 * i + 2]};
    g.normal[i] = {nrm[4 * i], nrm[4 * i + 1], nrm[4 * i + 2]};
    g.covered[i] = pos[4 * i + 3] > 0.5f ? 1 : 0;
  }
  return g;
}

std::vector<float> Renderer::read_shadow_depth(int* size) const {
  const Targets& t = *targets_;
  if (hooks_.technique == ShadowTechnique::Moments) {
    *size = moments_->size();
    return moments_->read_depth();
  }
  *size = t.shadow_size;
  std::vector<float> depth(static_cast<std::size_t>(t.shadow_size) * static_cast<std::size_t>(t.shadow_size));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.shadow_fbo.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, t.shadow_size, t.shadow_size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return depth;
}

std::vector<float> Renderer::read_cube_face(int face, int* size) const {
  if (!cube_ || face < 0 || face > 5) throw std::logic_error("read_cube_face needs a point light's cube shadow map");
  *size = cube_->size();
  return cube_->read_face(face);
}

std::vector<float> Renderer::read_moments(int* size) const {
  if (hooks_.technique != ShadowTechnique::Moments || !moments_)
    throw std::logic_error("read_moments needs a lab with the moments technique");
  *size = moments_->size();
  return moments_->read_moments();
}

MomentsTargetInfo Renderer::moments_targets() const {
  if (!moments_) return {};
  return moments_->query_targets();
}

std::vector<std::uint8_t> Renderer::shadow_map_image(int* size) const {
  if (hooks_.technique == ShadowTechnique::ShadowVolumes) {
    // Shadow volumes have no shadow map: a small grey placeholder keeps the outputs' shape.
    *size = 16;
    return std::vector<std::uint8_t>(16 * 16 * 4, 128);
  }
  if (cube_ && light_type_ == LightType::Point) {
    // The six faces at half resolution in a 3 x 3 grid, top row +X, -X, +Y, middle row -Y, +Z, -Z
    // (bottom row empty); distance from near (dark) to far (light), empty texels white.
    const int n = cube_->size(), half = std::max(n / 2, 1);
    *size = 3 * half;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(*size) * static_cast<std::size_t>(*size) * 4, 255);
    const float range = std::max(cube_views_.far_plane, 1e-6f);
    for (int f = 0; f < 6; ++f) {
      const std::vector<float> d = cube_->read_face(f);
      const int ox = (f % 3) * half, oy = (f / 3) * half;  // oy counted from the top
      for (int y = 0; y < half; ++y)
        for (int x = 0; x < half; ++x) {
          const float v = d[static_cast<std::size_t>(2 * y) * n + 2 * x];
          const int row = oy + (half - 1 - y);  // face rows are bottom first
          const std::size_t i = (static_cast<std::size_t>(row) * static_cast<std::size_t>(*size) + ox + x) * 4;
          const auto g = static_cast<std::uint8_t>(v >= kCubeEmptyDistance ? 255.0f : std::clamp(v / range, 0.0f, 1.0f) * 230.0f);
          rgba[i] = rgba[i + 1] = rgba[i + 2] = g;
        }
    }
    return rgba;
  }
  const std::vector<float> depth = read_shadow_depth(size);
  const int n = *size;
  // Stretch the occupied depth range to full contrast (the fitted ortho box already spans [0, 1], the
  // fixed tutorial box may not); the cleared background (depth 1) stays white.
  float lo = 1.0f, hi = 0.0f;
  for (float d : depth)
    if (d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
  const float scale = hi > lo ? 0.85f / (hi - lo) : 0.0f;
  std::vector<std::uint8_t> rgba(depth.size() * 4);
  for (std::size_t i = 0; i < depth.size(); ++i) {
    const float v = depth[i] >= 1.0f ? 1.0f : (depth[i] - lo) * scale;
    const auto g = static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
    rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = g;
    rgba[4 * i + 3] = 255;
  }
  flip_rows(rgba, n, n, 4);
  return rgba;
}

}  // namespace shadowlab
