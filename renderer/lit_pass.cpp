#include "renderer/lit_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/flashlight.h"
#include "core/image_io.h"
#include "renderer/debug_annotations.h"
#include "renderer/shadowed_light.h"
#include "renderer/volume_stencil.h"
#include "core/technique_params.h"

namespace shadowlab {

namespace {

// The material's textures take units from here up (the shadow techniques use the ones below).
constexpr int kMaterialFirstUnit = 8;

// A technique's overlay (LitOverlay) draws the same scene through the same vertex shader with its own
// fragment shader, blended over the lit image; it is never written into the G-buffer.
bool is_overlay(LitVariant variant) { return variant == LitVariant::Overlay; }
bool writes_gbuffer(LitVariant variant, bool gbuffer) { return gbuffer && !is_overlay(variant); }

// The texture unit of the material variant's base-colour texture (the shadow techniques use the first few).
constexpr int kBaseColorUnit = 6;

// Adds or removes the material variant's define (overlays never get it: they draw no materials).
void set_material_define(ProgramDesc& d, bool on) {
  std::erase_if(d.defines, [](const auto& def) { return def.first == "MATERIAL_TEXTURE"; });
  if (on && d.fragment == "shaders/lit.frag") d.defines.emplace_back("MATERIAL_TEXTURE", "1");
}

ProgramDesc lit_desc(const IncludeMap& includes, const IncludeRules& rules, bool gbuffer, LightType light,
                     LitVariant variant, const LitOverlay* overlay, bool materials, int lights, bool own_shadow_coords) {
  const bool remap = is_overlay(variant);
  if (remap && !overlay) throw std::logic_error("the lit pass's overlay variant needs the technique's shader");
  ProgramDesc d{"shaders/lit.vert", {}, remap ? overlay->fragment : "shaders/lit.frag", {}, includes, rules};
  if (gbuffer) d.defines.emplace_back("WRITE_GBUFFER", "1");
  if (!remap && light == LightType::Spot) d.defines.emplace_back("LIGHT_SPOT", "1");
  if (!remap && light == LightType::Point) d.defines.emplace_back("LIGHT_POINT", "1");
  if (lights > 0 && variant == LitVariant::Lit) d.defines.emplace_back("SHADOWED_LIGHTS", std::to_string(lights));
  if (variant == LitVariant::VolumeAmbient) d.defines.emplace_back("SHADOW_VOLUME_AMBIENT", "1");
  if (variant == LitVariant::VolumeAdditive) d.defines.emplace_back("SHADOW_VOLUME_ADDITIVE", "1");
  if (own_shadow_coords && !remap) d.defines.emplace_back(kOwnShadowCoordsDefine, "1");
  // The overlay's colours and their ranges, from the constants its legend reads.
  if (remap) d.defines.insert(d.defines.end(), overlay->defines.begin(), overlay->defines.end());
  set_material_define(d, materials);
  return d;
}

bool defines(const ProgramDesc& desc, const char* name) {
  return std::any_of(desc.defines.begin(), desc.defines.end(), [&](const auto& d) { return d.first == name; });
}

void resolve(const ReloadableProgram& program, LitUniforms& u) {
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
       Uniform(id, "u_light_position"),
       Uniform(id, "u_spot_direction"),
       Uniform(id, "u_spot_cos_cone"),
       Uniform(id, "u_light_near"),
       Uniform(id, "u_light_far"),
       Uniform(id, "u_texel_angle"),
       Uniform(id, "u_light_view_proj"),
       Uniform(id, "u_base_color"),
       Uniform(id, "u_alpha_cutoff"),
       {}};  // lights: below, for the SHADOWED_LIGHTS variant
  // A lab test that maps into the shadow map itself gets no matrix that does it (set() on no location
  // does nothing): declaring the uniform gives it zeros.
  if (defines(program.desc(), kOwnShadowCoordsDefine)) u.light_tex_matrix = Uniform();
  for (int i = 0; i < kMaxShadowedLights; ++i) {
    const std::string at = "[" + std::to_string(i) + "]", field = "u_lights" + at + ".";
    const auto f = [&](const char* name) { return Uniform(id, (field + name).c_str()); };
    u.lights.entry[i] = {Uniform(id, ("u_light_maps" + at).c_str()), f("tex_matrix"), f("position"), f("direction"),
                         f("cos_cone"), f("near"), f("far"), f("texel_angle"), f("bias_slope"), f("intensity")};
  }
  u.lights.sun_intensity = Uniform(id, "u_sun_intensity");
}

}  // namespace

bool LitPass::build(const IncludeMap& includes, const IncludeRules& rules, LightType light,
                    const ShadowPass::Shape& shape, int lights, bool own_shadow_coords) {
  bool ok = true;
  const LitOverlay* overlay = shape.overlay ? &*shape.overlay : nullptr;
  for (LitVariant variant : shape.lit_variants)
    for (bool gbuffer : {false, true}) {
      if (gbuffer && !writes_gbuffer(variant, true)) continue;
      Slot& slot = programs_[{variant, gbuffer}];
      slot.specialised.clear();  // built from the old includes; made again when drawn
      slot.failed.clear();
      slot.generic.program.set_desc(
          lit_desc(includes, rules, gbuffer, light, variant, overlay, materials_, lights, own_shadow_coords));
      ok = slot.generic.program.rebuild() && ok;
    }
  return ok;
}

void LitPass::use_materials(bool on) {
  if (on == materials_) return;
  materials_ = on;
  // The same programs with the material variant's define added or taken out, built again.
  for (auto& [key, slot] : programs_) {
    slot.specialised.clear();
    slot.failed.clear();
    ProgramDesc d = slot.generic.program.desc();
    set_material_define(d, on);
    slot.generic.program.set_desc(std::move(d));
    slot.generic.program.rebuild();
  }
}

void LitPass::keep_only(const std::vector<LitVariant>& variants) {
  std::erase_if(programs_, [&](const auto& entry) {
    return std::find(variants.begin(), variants.end(), entry.first.first) == variants.end();
  });
}

void LitPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  for (auto& [key, slot] : programs_) {
    f(slot.generic.program);
    for (auto& [constants, p] : slot.specialised) f(p->program);
  }
}

LitPass::Program& LitPass::program_for(Slot& slot) {
  // drawn_constants_ is assigned over (not cleared first): its strings keep their storage.
  const auto generic = [&]() -> Program& {
    drawn_constants_.clear();
    return slot.generic;
  };
  if (!specialise_ || constants_.empty()) return generic();
  for (auto& [constants, p] : slot.specialised)
    if (constants == constants_) {
      drawn_constants_ = constants_;
      return *p;
    }
  for (const auto& [constants, generation] : slot.failed)
    if (constants == constants_ && generation == slot.generic.program.generation()) return generic();
  // First drawn with these constants: the generic program's files (as it was last built) with them in.
  ProgramDesc desc = slot.generic.program.desc();
  desc.constants = constants_;
  auto p = std::make_unique<Program>();
  p->program.set_desc(std::move(desc));
  if (!slot.generic.program.valid() || !p->program.rebuild()) {
    slot.failed.emplace_back(constants_, slot.generic.program.generation());
    return generic();
  }
  drawn_constants_ = constants_;
  slot.specialised.emplace_back(constants_, std::move(p));
  return *slot.specialised.back().second;
}

void LitPass::ensure_targets(int width, int height, bool gbuffer, bool stencil, bool to_window, GLuint window) {
  if (to_window && gbuffer) throw std::logic_error("the window's framebuffer has no G-buffer");
  to_window_ = to_window;
  window_ = window;
  if (to_window) {  // drawn where it is seen: no targets of its own are made (those made before stay)
    if (width != width_ || height != height_) fbo_ = {};
    width_ = width;
    height_ = height;
    return;
  }
  if (fbo_ && width == width_ && height == height_ && gbuffer == gbuffer_ && stencil == stencil_) return;
  color_ = make_texture_2d(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR);
  depth_ = GlRenderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24, width, height);
  fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            depth_.id());
  // The G-buffer attachments exist only when a check asks for them.
  visibility_ = {};
  position_ = {};
  normal_ = {};
  if (gbuffer) {
    visibility_ = make_texture_2d(GL_R32F, width, height, GL_RED, GL_FLOAT, GL_NEAREST);
    position_ = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
    normal_ = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, visibility_.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, position_.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, normal_.id(), 0);
  }
  check_framebuffer("view");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  width_ = width;
  height_ = height;
  gbuffer_ = gbuffer;
  stencil_ = stencil;
}

void LitPass::draw(PassContext& ctx, LitVariant variant) {
  if (!ctx.lit_inputs) throw std::logic_error("the lit pass draws a frame whose context has no lit inputs");
  const LitInputs& inputs = *ctx.lit_inputs;
  use_materials(ctx.gpu_scene.has_materials());
  const auto it = programs_.find({variant, writes_gbuffer(variant, ctx.gbuffer)});
  if (it == programs_.end()) throw std::logic_error("the lit pass has no program for this variant");
  Program& p = program_for(it->second);
  if (!ctx.lights || ctx.lights->empty()) throw std::logic_error("the lit pass draws a frame with no light");
  const ShadowPass& technique = ctx.lights->front().pass();
  if (p.u.generation != p.program.generation() || p.test != inputs.test || p.pass_serial != technique.serial()) {
    resolve(p.program, p.u);
    // The shadow test's and the technique's own uniforms, each looked up by its owner on this program.
    p.test = inputs.test;
    p.test_bind = p.test && p.test->resolve ? p.test->resolve(p.program.id()) : ShadowTestBind();
    p.pass_serial = technique.serial();
    p.pass_bind = technique.lit_bind(p.program.id());
  }
  if (is_overlay(variant)) {
    bind_color_target(framebuffer(), width_, height_);  // a tint over the picture; the G-buffer stays as drawn
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer());
    glViewport(0, 0, width_, height_);
  }
  begin(variant, ctx.gbuffer, to_window_ && window_ == 0);
  glUseProgram(p.program.id());
  set_uniforms(ctx, p);
  bind_material(p.program, ctx);
  ctx.gpu_scene.bind();
  if (!materials_) {
    for (const auto& range : ctx.gpu_scene.ranges()) {
      ctx.gpu_scene.draw(range);
      ++ctx.stats.draws;
    }
  } else {
    // Opaque and masked meshes first; BLEND meshes after them (in the plain lit view: blended over what
    // is behind, without writing depth; in the shadow-volume passes as opaque).
    p.u.base_color.set(kBaseColorUnit);
    const bool blend_after = variant == LitVariant::Lit;
    for (int round = 0; round < (blend_after ? 2 : 1); ++round) {
      if (round == 1) {
        glDepthMask(GL_FALSE);
        glEnablei(GL_BLEND, 0);  // colour only: the G-buffer takes the front surface's values as they are
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
      }
      for (const auto& range : ctx.gpu_scene.ranges()) {
        const bool blend = range.alpha_mode == AlphaMode::Blend;
        if (blend_after && blend != (round == 1)) continue;
        ctx.gpu_scene.bind_texture(range, kBaseColorUnit);
        p.u.alpha_cutoff.set(range.alpha_mode == AlphaMode::Mask ? range.alpha_cutoff : blend && blend_after ? -2.0f : -1.0f);
        ctx.gpu_scene.draw(range);
        ++ctx.stats.draws;
      }
    }
  }
  end();
}

void LitPass::set_material(const std::map<std::string, MaterialTexture>& textures,
                           const std::map<std::string, std::string>& params) {
  material_textures_.clear();
  for (const auto& [name, t] : textures) {
    if (t.width <= 0 || t.height <= 0 || t.rgba.size() != static_cast<std::size_t>(t.width) * t.height * 4)
      throw std::invalid_argument("material texture " + name + ": texels do not match its size");
    GlTexture tex = make_texture_2d(GL_RGBA8, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, tex.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    material_textures_.emplace_back(name, std::move(tex));
  }
  material_params_ = params;
  material_locations_.clear();
}

void LitPass::bind_material(const ReloadableProgram& program, const PassContext& ctx) const {
  if (material_textures_.empty() && material_params_.empty()) return;
  // The material's uniform locations, looked up once per program build (textures, then parameters, then
  // u_floor_height).
  auto& cached = material_locations_[program.id()];
  if (cached.first != program.generation() || cached.second.empty()) {
    cached.first = program.generation();
    cached.second.clear();
    for (const auto& entry : material_textures_) cached.second.push_back(glGetUniformLocation(program.id(), entry.first.c_str()));
    for (const auto& entry : material_params_) cached.second.push_back(glGetUniformLocation(program.id(), entry.first.c_str()));
    cached.second.push_back(glGetUniformLocation(program.id(), "u_floor_height"));
  }
  const std::vector<GLint>& at = cached.second;
  std::size_t k = 0;
  int unit = kMaterialFirstUnit;
  for (const auto& entry : material_textures_) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, entry.second.id());
    glBindSampler(static_cast<GLuint>(unit), 0);
    glUniform1i(at[k++], unit);
    ++unit;
  }
  glActiveTexture(GL_TEXTURE0);
  for (const auto& entry : material_params_) glUniform1f(at[k++], ctx.params.get_float(entry.second));
  glUniform1f(at[k], ctx.gpu_scene.bounds().min.y);
}

void LitPass::begin(LitVariant variant, bool gbuffer, bool default_framebuffer) const {
  const GLenum window[] = {GL_BACK};
  const GLenum all[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glEnable(GL_DEPTH_TEST);
  switch (variant) {
    case LitVariant::Lit:
    case LitVariant::VolumeAmbient: {  // the view from scratch: colour, depth (and the G-buffer)
      glDrawBuffers(gbuffer ? 4 : 1, default_framebuffer ? window : all);
      glDepthMask(GL_TRUE);
      glDepthFunc(GL_LESS);
      const float background[] = {0.16f, 0.18f, 0.22f, 1.0f};
      const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
      glClearBufferfv(GL_COLOR, 0, background);
      if (gbuffer)
        for (int i = 1; i < 4; ++i) glClearBufferfv(GL_COLOR, i, zero);  // position.w = 0 marks background
      glClear(GL_DEPTH_BUFFER_BIT);
      break;
    }
    case LitVariant::VolumeAdditive: {
      // Colour and visibility only; positions and normals stay as the ambient pass wrote them.
      const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_NONE, GL_NONE};
      glDrawBuffers(gbuffer ? 4 : 1, default_framebuffer ? window : buffers);
      code_.begin_additive_lit_pass();  // stencil == 0, depth equal, added (lab 9's GL exercise)
      break;
    }
    case LitVariant::Overlay:
      // The same vertices through the same vertex shader give the same depths: LEQUAL keeps exactly the
      // visible surfaces.
      glDepthFunc(GL_LEQUAL);
      glDepthMask(GL_FALSE);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      break;
  }
}

void LitPass::end() {
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void LitPass::set_uniforms(const PassContext& ctx, const Program& p) const {
  const LitUniforms& u = p.u;
  const LitInputs& inputs = *ctx.lit_inputs;
  const FrameLight& light = ctx.light;
  const ParamSet& params = ctx.params;
  const std::vector<ShadowedLight>& lights = *ctx.lights;
  const int map_size = lights.front().pass().size();  // the frame light's map: a texel's depth and angle
  u.view_proj.set(ctx.camera_view_proj());
  u.light_tex_matrix.set(clip_to_texture() * light.view.view_projection());
  u.light_view_proj.set(light.view.view_projection());
  u.to_light.set(light.to_light);
  u.bias_constant.set(params.get(param::shadow_bias));
  u.bias_slope.set(params.get(param::shadow_slope_bias));
  // One shadow-map texel's world size, in the depth units the comparison uses ([0, 1] over the ortho
  // box's depth): a slope-scaled bias in texels multiplies this by tan(angle of incidence).
  const float depth_range = 2.0f / std::abs(light.view.projection[2][2]);
  u.texel_depth.set(light.view.world_size.x / static_cast<float>(map_size) / depth_range);
  u.ambient.set(params.get(param::view_ambient));
  // Positional lights: where the light stands, the spot's cone, its projection's planes, a texel's angle.
  u.light_position.set(light.position);
  u.spot_direction.set(light.spot_direction);
  u.spot_cos_cone.set(std::cos(glm::radians(light.spot_cone_deg)));
  const glm::mat4& proj = light.view.projection;  // near and far back from a perspective matrix
  u.light_near.set(proj[3][2] / (proj[2][2] - 1.0f));
  u.light_far.set(proj[3][2] / (proj[2][2] + 1.0f));
  u.texel_angle.set(light.texel_angle(std::max(map_size, 1)));
  if (lights.size() > 1) {  // each uniform set when present: an answer may leave some unused
    u.lights.sun_intensity.set(static_cast<float>(params.get(param::sun_intensity)));
    for (std::size_t i = 1; i < lights.size(); ++i)
      lights[i].bind_lit_inputs(params, u.lights.entry[i - 1], kShadowedLightUnits[i - 1]);
    glActiveTexture(GL_TEXTURE0);
  }
  // The frame light's map and its technique's uniforms, as its pass binds them (leaves unit 0 active).
  p.pass_bind(params);
  // The shadow test's own uniforms (only the selected test's: renderer/shadow_test.h).
  if (p.test_bind) p.test_bind(ShadowTestFrame{params, light, inputs.matched_radius, ctx.annotations});
  u.shadow_map.set(0);
}

std::vector<std::uint8_t> LitPass::read_color() const {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  flip_rows(rgba, width_, height_, 4);
  return rgba;
}

std::vector<float> LitPass::read_visibility() const {
  if (!gbuffer_) throw std::logic_error("read_visibility needs a frame rendered with gbuffer = true");
  return read_pixels(fbo_.id(), GL_COLOR_ATTACHMENT1, width_, height_, GL_RED, 1);
}

GBuffer LitPass::read_gbuffer() const {
  if (!gbuffer_) throw std::logic_error("read_gbuffer needs a frame rendered with gbuffer = true");
  const auto pos = read_pixels(fbo_.id(), GL_COLOR_ATTACHMENT2, width_, height_, GL_RGBA, 4);
  const auto nrm = read_pixels(fbo_.id(), GL_COLOR_ATTACHMENT3, width_, height_, GL_RGBA, 4);
  GBuffer g;
  g.width = width_;
  g.height = height_;
  const std::size_t n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
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

void LitPass::present(GLuint framebuffer, int width, int height) const {
  if (to_window_) throw std::logic_error("the view was drawn into the window: nothing to present");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

}  // namespace shadowlab
