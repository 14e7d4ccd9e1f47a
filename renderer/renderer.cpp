#include "renderer/renderer.h"

#include <chrono>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "renderer/image_io.h"
#include "renderer/moments_pass.h"
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
          {"moments_passes", moments_passes}, {"blur_passes", blur_passes}, {"draws", draws}};
}

std::map<std::string, std::string> Renderer::default_includes(ShadowTechnique technique) {
  std::map<std::string, std::string> includes = {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
                                                 {"lab/visibility.glsl", "shaders/shadow/hard.glsl"}};
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
};

struct Renderer::Programs {
  ReloadableProgram shadow_depth, lit, lit_gbuffer, debug_quad;
  ReloadableProgram remap_view;  // moments technique only; empty (skipped by all()) otherwise
  // Uniform locations, resolved once per program generation.
  struct Shadow {
    int generation = -1;
    Uniform light_view_proj;
  } shadow;
  LitUniforms lit_u, lit_gbuffer_u, remap_view_u;
  struct Quad {
    int generation = -1;
    Uniform depth_map, rect;
  } quad;

  void all(const std::function<void(ReloadableProgram&)>& f) {
    f(shadow_depth);
    f(lit);
    f(lit_gbuffer);
    f(debug_quad);
    if (!remap_view.desc().fragment.empty()) f(remap_view);
  }
};

namespace {

ProgramDesc lit_desc(const std::map<std::string, std::string>& includes, bool gbuffer) {
  ProgramDesc d{"shaders/lit.vert", {}, "shaders/lit.frag", {}, {}};
  if (gbuffer) d.defines.emplace_back("WRITE_GBUFFER", "1");
  for (const auto& [k, v] : includes) d.includes[k] = v;
  return d;
}

GLenum depth_internal_format(const std::string& name) {
  if (name == "16") return GL_DEPTH_COMPONENT16;
  if (name == "32F") return GL_DEPTH_COMPONENT32F;
  return GL_DEPTH_COMPONENT24;
}

GlTexture make_texture(GLenum internal_format, int w, int h, GLenum format, GLenum type, GLenum filter) {
  GlTexture t = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), w, h, 0, format, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

void check_framebuffer(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    std::ostringstream s;
    s << what << " framebuffer is incomplete (status 0x" << std::hex << status << ")";
    throw std::runtime_error(s.str());
  }
}

// Times one pass with a GL_TIME_ELAPSED query, read at once: on llvmpipe the pass has finished by then
// anyway, and it keeps per-pass figures exact for the benchmark. A GPU time cannot exceed the wall time
// around it; llvmpipe breaks that for the first timed pass of a new context's first frame (the query's
// start reads as 0, giving the machine's uptime: 3.3e6 ms measured), so there the glFinish-bracketed
// wall time is used instead (within ~0.3 ms of the query where both work, shared/NOTES.md) and the pass
// is marked. Later frames measured clean (test PassTimesArePlausible).
template <typename F>
void timed(GLuint query, const char* name, FrameStats& stats, F&& pass) {
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
  const bool plausible = gpu_ms <= wall_ms + 1.0;
  stats.passes.push_back({name, plausible ? gpu_ms : wall_ms, !plausible});
}

}  // namespace

Renderer::Renderer()
    : targets_(std::make_unique<Targets>()),
      programs_(std::make_unique<Programs>()),
      empty_vao_(GlVertexArray::create()),
      timer_(GlQuery::create()) {
  programs_->shadow_depth = ReloadableProgram({"shaders/shadow_depth.vert", {}, "shaders/shadow_depth.frag", {}, {}});
  programs_->debug_quad = ReloadableProgram({"shaders/fullscreen.vert", {}, "shaders/debug_depth.frag", {}, {}});
  if (!set_lab({})) throw std::runtime_error("cannot build the renderer's shaders:\n" + shader_error());
}

Renderer::~Renderer() = default;

void Renderer::set_scene(const Scene& scene) {
  scene_ = scene;
  gpu_scene_ = std::make_unique<GpuScene>(scene_);
  shadow_state_.clear();
}

bool Renderer::set_lab(const LabHooks& hooks) {
  const bool moments = hooks.technique == ShadowTechnique::Moments;
  auto includes = default_includes(hooks.technique);
  for (const auto& [k, v] : hooks.includes) includes[k] = v;
  Programs& p = *programs_;
  p.lit.set_desc(lit_desc(includes, false));
  p.lit_gbuffer.set_desc(lit_desc(includes, true));
  if (moments) {
    ProgramDesc remap = lit_desc(includes, false);
    remap.fragment = "shaders/vsm/remap_view.frag";
    p.remap_view.set_desc(remap);
  }
  bool ok = true;
  p.all([&](ReloadableProgram& program) { ok = program.rebuild() && ok; });
  if (moments) {
    if (!moments_) moments_ = std::make_unique<MomentsPass>();
    ok = moments_->set_includes({includes.begin(), includes.end()}) && ok;
  }
  if (ok) {
    hooks_ = hooks;
    if (!moments) {
      moments_.reset();  // a depth lab keeps no moments targets or programs
      p.remap_view = {};
      p.remap_view_u = {};
    }
  }
  shadow_state_.clear();
  return ok;
}

void Renderer::for_each_program(const std::function<void(ReloadableProgram&)>& f) const {
  programs_->all(f);
  if (moments_) moments_->for_each_program(f);
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

namespace {
// A vsm.* choice: the lab's value when it declares the key, else the declared default.
std::string vsm_choice(const ParamSet& params, const std::string& key) {
  if (params.find(key)) return params.get_choice(key);
  const ParamSpec spec = vsm_param_specs({key}).at(0);
  return spec.choices.at(static_cast<std::size_t>(spec.default_value));
}
}  // namespace

int Renderer::shadow_map_size() const {
  return moments_ && hooks_.technique == ShadowTechnique::Moments ? moments_->size() : targets_->shadow_size;
}

void Renderer::ensure_targets(const ParamSet& params, const FrameRequest& request) {
  Targets& t = *targets_;
  const int size = std::stoi(params.get_choice("shadow.map_size"));
  const std::string& format = params.get_choice("shadow.depth_format");
  if (hooks_.technique == ShadowTechnique::Moments) {
    // The moments pass brings its own colour texture and depth renderbuffer: no depth texture.
    t.shadow_depth = {};
    t.shadow_fbo = {};
    t.shadow_size = 0;
    t.depth_format.clear();
    const bool blur = static_cast<int>(vsm_param(params, "vsm.blur_radius")) > 0;
    if (moments_->ensure_targets(size, vsm_choice(params, "vsm.format"), blur)) shadow_state_.clear();
  } else if (size != t.shadow_size || format != t.depth_format) {
    t.shadow_depth = make_texture(depth_internal_format(format), size, size, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NEAREST);
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
  if (request.width != t.width || request.height != t.height || request.gbuffer != t.gbuffer) {
    const int w = request.width, h = request.height;
    t.color = make_texture(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR);
    t.depth = GlRenderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, t.depth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    t.view_fbo = GlFramebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth.id());
    // The G-buffer attachments exist only when a check asks for them.
    t.visibility = {};
    t.position = {};
    t.normal = {};
    if (request.gbuffer) {
      t.visibility = make_texture(GL_R32F, w, h, GL_RED, GL_FLOAT, GL_NEAREST);
      t.position = make_texture(GL_RGBA32F, w, h, GL_RGBA, GL_FLOAT, GL_NEAREST);
      t.normal = make_texture(GL_RGBA32F, w, h, GL_RGBA, GL_FLOAT, GL_NEAREST);
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

const FrameStats& Renderer::render(const ParamSet& params, const FrameRequest& request) {
  if (!gpu_scene_) throw std::logic_error("Renderer::render called before set_scene");
  const auto cpu_start = std::chrono::steady_clock::now();
  stats_.passes.clear();
  ++stats_.frames;
  ensure_targets(params, request);
  width_ = request.width;
  height_ = request.height;

  // 1. The light: its direction from the sliders, its view and projection from the lab's fit.
  to_light_ = direction_from_angles(params.get_float("light.azimuth"), params.get_float("light.elevation"));
  const Bounds bounds = scene_.bounds();
  light_view_ = hooks_.light_fit ? hooks_.light_fit(bounds, to_light_) : fit_light_ortho(bounds, to_light_);
  camera_view_ = request.camera.view();
  camera_projection_ = request.camera.projection(static_cast<float>(request.width) / static_cast<float>(request.height));

  // 2. Shadow pass, only when what it depends on changed (light, casters, map settings, shaders).
  std::string state(reinterpret_cast<const char*>(&light_view_.view), sizeof(glm::mat4) * 1);
  state.append(reinterpret_cast<const char*>(&light_view_.projection), sizeof(glm::mat4));
  state += params.get_choice("shadow.cull") + (hooks_.shadow_cull_override ? std::to_string(hooks_.shadow_cull_override()) : "");
  const bool moments = hooks_.technique == ShadowTechnique::Moments;
  if (moments) {
    // The blur overwrites the moments it read (ping-pong back into A), so its settings are inputs of
    // the moments pass too.
    state += "moments " + vsm_choice(params, "vsm.format");
    state += " r" + std::to_string(vsm_param(params, "vsm.blur_radius"));
    state += " s" + std::to_string(vsm_param(params, "vsm.blur_sigma"));
  }
  if (state != shadow_state_) {
    if (moments) {
      moments_passes(params);
    } else {
      timed(timer_.id(), "shadow", stats_, [&] { shadow_pass(params); });
    }
    ++stats_.shadow_passes;
    shadow_state_ = state;
  }

  // 3. Lit pass from the camera, reading the shadow map (or the moments).
  timed(timer_.id(), "lit", stats_, [&] { lit_pass(params, request); });

  // 4. Debug views.
  if (moments && vsm_param(params, "vsm.show_remap") != 0.0)
    timed(timer_.id(), "remap_view", stats_, [&] { remap_view_pass(params); });
  if (params.get_bool("view.debug_quad")) timed(timer_.id(), "debug_quad", stats_, [&] { debug_quad_pass(params); });

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  stats_.cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start).count();
  return stats_;
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
  gpu_scene_->bind();
  for (const auto& range : gpu_scene_->ranges()) {
    if (!range.casts_shadow) continue;
    gpu_scene_->draw(range);
    ++stats_.draws;
  }
  glDisable(GL_CULL_FACE);
}

void Renderer::moments_passes(const ParamSet& params) {
  MomentsPass& m = *moments_;
  const int cull =
      hooks_.shadow_cull_override ? hooks_.shadow_cull_override() : static_cast<int>(params.get("shadow.cull"));
  // 2a. The moments (z, z^2 + slope term) of the nearest surface per texel.
  timed(timer_.id(), "moments", stats_,
        [&] { m.draw_moments(*gpu_scene_, light_view_.view_projection(), cull, stats_.draws); });
  ++stats_.moments_passes;
  // 2b. The separable Gaussian over the moments: X then Y. Radius 0 runs neither (and ensure_targets
  // allocated no ping-pong texture).
  const int radius = static_cast<int>(vsm_param(params, "vsm.blur_radius"));
  const auto sigma = static_cast<float>(vsm_param(params, "vsm.blur_sigma"));
  if (radius > 0) {
    timed(timer_.id(), "blur_x", stats_, [&] { m.blur(0, radius, sigma, empty_vao_.id()); });
    timed(timer_.id(), "blur_y", stats_, [&] { m.blur(1, radius, sigma, empty_vao_.id()); });
    stats_.blur_passes += 2;
  }
}

void Renderer::set_lit_uniforms(const ParamSet& params, LitUniforms& u) {
  u.view_proj.set(camera_projection_ * camera_view_);
  u.light_tex_matrix.set(clip_to_texture() * light_view_.view_projection());
  u.to_light.set(to_light_);
  u.bias_constant.set(params.get_float("shadow.bias"));
  u.bias_slope.set(params.get_float("shadow.slope_bias"));
  // One shadow-map texel's world size, in the depth units the comparison uses ([0, 1] over the ortho
  // box's depth): a slope-scaled bias in texels multiplies this by tan(angle of incidence).
  const float depth_range = 2.0f / std::abs(light_view_.projection[2][2]);
  u.texel_depth.set(light_view_.world_size.x / static_cast<float>(shadow_map_size()) / depth_range);
  u.ambient.set(params.get_float("view.ambient"));
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
       Uniform(id, "u_bleed_delta")};
}

void Renderer::remap_view_pass(const ParamSet& params) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  if (p.remap_view_u.generation != p.remap_view.generation()) resolve_lit_uniforms(p.remap_view, p.remap_view_u);
  glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
  const GLenum color_only = GL_COLOR_ATTACHMENT0;  // a tint over the picture; the G-buffer stays as drawn
  glDrawBuffers(1, &color_only);
  glViewport(0, 0, t.width, t.height);
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

void Renderer::debug_quad_pass(const ParamSet&) {
  Targets& t = *targets_;
  Programs& p = *programs_;
  if (hooks_.technique == ShadowTechnique::Moments) {
    // Three quads along the bottom right, left to right: E[z], E[z^2] and the variance.
    glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
    const GLenum color_only = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &color_only);
    glDisable(GL_DEPTH_TEST);
    const int side = t.height / 4;
    for (int channel = 0; channel < 3; ++channel) {
      glViewport(t.width - (3 - channel) * (side + 8), 8, side, side);
      moments_->draw_debug_quad(channel, empty_vao_.id());
    }
    glEnable(GL_DEPTH_TEST);
    glViewport(0, 0, t.width, t.height);
    return;
  }
  if (p.quad.generation != p.debug_quad.generation()) {
    p.quad = {p.debug_quad.generation(), Uniform(p.debug_quad.id(), "u_depth_map"), Uniform(p.debug_quad.id(), "u_rect")};
  }
  glBindFramebuffer(GL_FRAMEBUFFER, t.view_fbo.id());
  const GLenum color_only = GL_COLOR_ATTACHMENT0;  // the quad must not overwrite the G-buffer
  glDrawBuffers(1, &color_only);
  glDisable(GL_DEPTH_TEST);
  // A square in the lower-right corner (the panel sits on the left), a quarter of the frame height.
  const int side = t.height / 4;
  glViewport(t.width - side - 8, 8, side, side);
  glUseProgram(p.debug_quad.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, t.shadow_depth.id());
  p.quad.depth_map.set(0);
  p.quad.rect.set(glm::vec4(0, 0, 1, 1));
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glViewport(0, 0, t.width, t.height);
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
