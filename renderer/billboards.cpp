#include "renderer/billboards.h"

#include <algorithm>
#include <cmath>

#include "renderer/shadow_pass.h"

namespace shadowlab {

namespace {

constexpr float kTau = 6.28318530718f;

glm::vec3 eye_of(const glm::mat4& view) { return glm::vec3(glm::inverse(view)[3]); }
// (The lab's two programs are drawn once a frame each: their uniforms are looked up as they are set.)

}  // namespace

float billboard_alpha(glm::vec2 uv) {
  const float x = std::abs(uv.x - 0.5f);
  const float trunk = (x < 0.05f && uv.y < 0.4f) ? 1.0f : 0.0f;
  const glm::vec2 d(x / 0.45f, (uv.y - 0.62f) / 0.36f);
  const float crown = std::clamp(2.0f * (1.0f - glm::length(d)), 0.0f, 1.0f);
  const float leaves = 0.65f + 0.35f * std::cos(kTau * 5.0f * x) * std::cos(kTau * 5.0f * uv.y);
  return std::max(trunk, crown * leaves);
}

BillboardSize billboard_size(const ParamSet& params) {
  return {params.get(param::billboard_width), params.get(param::billboard_height), params.get(param::billboard_cutoff)};
}

namespace param {

const FloatParam billboard_width{{"billboard.width", "Tree width", ParamKind::Float, BillboardSize{}.width, 0.2, 4.0,
    "The billboards' width, world units.", {}, kInvalidatesShadowMap}};
const FloatParam billboard_height{{"billboard.height", "Tree height", ParamKind::Float, BillboardSize{}.height, 0.2,
    4.0, "The billboards' height, world units.", {}, kInvalidatesShadowMap}};
const FloatParam billboard_cutoff{{"billboard.cutoff", "Alpha cutoff", ParamKind::Float, BillboardSize{}.cutoff, 0.05,
    0.95, "Points of the tree whose alpha is below this are cut out, in the view and (the lab's alpha test) in the "
    "shadow map.",
    {}, kInvalidatesShadowMap}};
const BoolParam billboard_show_shadow_quads{{"billboard.show_shadow_quads", "Show the shadow pass's quads",
    ParamKind::Bool, 0, 0, 1,
    "Draws the quads the shadow pass draws (your shadow_quad and shadow_keeps) in the view, in magenta.", {}}};

}  // namespace param

std::vector<ParamSpec> billboard_param_specs() {
  return specs_of(param::billboard_width, param::billboard_height, param::billboard_cutoff,
                  param::billboard_show_shadow_quads);
}

Mesh billboard_light_quads(const std::vector<glm::vec3>& bases, const BillboardSize& size, const glm::vec3& to_light) {
  Mesh m;
  m.name = "billboards (light-facing)";
  m.color = glm::vec3(0.2f, 0.45f, 0.16f);
  m.alpha_mode = AlphaMode::Mask;
  m.alpha_cutoff = size.cutoff;
  m.shape_alpha = &billboard_alpha;
  const glm::vec3 right = glm::normalize(glm::vec3(to_light.z, 0.0f, -to_light.x)) * size.width;
  const glm::vec3 up(0.0f, size.height, 0.0f);
  const glm::vec3 normal = glm::normalize(glm::cross(right, up));
  for (const glm::vec3& base : bases) {
    const auto first = static_cast<std::uint32_t>(m.positions.size());
    for (int i = 0; i < 4; ++i) {
      const glm::vec2 uv(static_cast<float>(i & 1), static_cast<float>(i >> 1));
      m.positions.push_back(base + (uv.x - 0.5f) * right + uv.y * up);
      m.normals.push_back(normal);
      m.uvs.push_back(uv);
    }
    m.indices.insert(m.indices.end(), {first, first + 1, first + 2, first + 2, first + 1, first + 3});
  }
  return m;
}

BillboardPass::BillboardPass()
    : shadow_({"shaders/billboard/billboard.vert", "shaders/billboard/shadow.geom", "shaders/billboard/shadow.frag",
    {}, {}}),
      view_({"shaders/billboard/billboard.vert", "shaders/billboard/view.geom", "shaders/billboard/view.frag", {},
    {}}) {}

bool BillboardPass::set_includes(const std::map<std::string, std::filesystem::path>& includes, const IncludeRules& rules) {
  ProgramDesc desc = shadow_.desc();
  desc.includes = includes;
  desc.includes.emplace("lab/billboard.glsl", "shaders/billboard/shadow_quad.glsl");  // unless a lab gives one
  desc.rules = rules;
  shadow_.set_desc(desc);
  const bool shadow_ok = shadow_.rebuild();
  return view_.rebuild() && shadow_ok;
}

void BillboardPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(shadow_);
  f(view_);
}

void BillboardPass::set_points(const std::vector<glm::vec3>& bases, const Placement& placement) {
  // Called every frame: a still frame compares in place and allocates nothing.
  bool same = vao_ && bases.size() == uploaded_.size();
  for (std::size_t i = 0; same && i < bases.size(); ++i) same = placement.to_local(bases[i]) == uploaded_[i];
  if (same) return;
  std::vector<glm::vec3> local;
  local.reserve(bases.size());
  for (const glm::vec3& p : bases) local.push_back(placement.to_local(p));
  if (!vao_) {
    vao_ = GlVertexArray::create();
    points_ = GlBuffer::create();
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, points_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(local.size() * sizeof(glm::vec3)), local.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindVertexArray(0);
  uploaded_ = std::move(local);
  count_ = uploaded_.size();
}

void BillboardPass::draw_shadow_program(const PassContext& ctx, const glm::mat4& view_proj) {
  const BillboardSize size = billboard_size(ctx.params);
  const ShadowUniforms& u = shadow_u_.get(shadow_, [](GLuint id) {
    return ShadowUniforms{{id, "u_light_view_proj"}, {id, "u_to_light"}, {id, "u_eye"}, {id, "u_size"}, {id,
    "u_cutoff"}};
  });
  glUseProgram(shadow_.id());
  u.view_proj.set(view_proj);
  u.to_light.set(ctx.light.to_light);
  u.eye.set(eye_of(ctx.camera_view));
  u.size.set(glm::vec2(size.width, size.height));
  u.cutoff.set(size.cutoff);
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count_));
}

void BillboardPass::draw_shadow(const PassContext& ctx, const glm::mat4& light_view_proj) {
  if (count_ == 0) return;
  // Both faces: a quad turned either way casts the same shadow.
  glDisable(GL_CULL_FACE);
  draw_shadow_program(ctx, light_view_proj);
}

void BillboardPass::draw_view(const PassContext& ctx, bool show_shadow_quads) {
  if (count_ == 0) return;
  const BillboardSize size = billboard_size(ctx.params);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  const ViewUniforms& u = view_u_.get(view_, [](GLuint id) {
    return ViewUniforms{{id, "u_view_proj"}, {id, "u_eye"}, {id, "u_size"}, {id, "u_cutoff"}, {id, "u_ambient"}};
  });
  glUseProgram(view_.id());
  u.view_proj.set(ctx.camera_view_proj());
  u.eye.set(eye_of(ctx.camera_view));
  u.size.set(glm::vec2(size.width, size.height));
  u.cutoff.set(size.cutoff);
  u.ambient.set(ctx.params.get(param::view_ambient));
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count_));
  if (show_shadow_quads) draw_shadow_program(ctx, ctx.camera_view_proj());
}

}  // namespace shadowlab
