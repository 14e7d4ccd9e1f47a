#include "renderer/shadow_passes.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "renderer/cascade_pass.h"
#include "renderer/cube_shadow_pass.h"
#include "renderer/depth_map_pass.h"
#include "core/image_io.h"
#include "renderer/moments_pass.h"
#include "renderer/msm_pass.h"
#include "renderer/shadow_volume_pass.h"

namespace shadowlab {

namespace {

template <typename Pass>
std::unique_ptr<ShadowPass> make() {
  return std::make_unique<Pass>();
}

bool any_light(LightType) { return true; }

const ShadowPassEntry kEntries[] = {
    {ShadowTechnique::Depth, [](LightType l) { return l != LightType::Point; }, &DepthMapPass::default_includes,
     &make<DepthMapPass>},
    {ShadowTechnique::Depth, [](LightType l) { return l == LightType::Point; }, &CubeShadowPass::default_includes,
     &make<CubeShadowPass>},
    {ShadowTechnique::Moments, &any_light, &MomentsPass::default_includes, &make<MomentsPass>},
    {ShadowTechnique::ShadowVolumes, &any_light, &ShadowVolumePass::default_includes, &make<ShadowVolumePass>},
    {ShadowTechnique::MomentShadowMaps, &any_light, &MsmPass::default_includes, &make<MsmPass>},
    {ShadowTechnique::CascadedShadowMaps, [](LightType l) { return l == LightType::Directional; },
     &CascadePass::default_includes, &make<CascadePass>},
};

}  // namespace

const ShadowPassEntry& shadow_pass_entry(ShadowTechnique technique, LightType light) {
  for (const auto& entry : kEntries)
    if (entry.technique == technique && entry.serves(light)) return entry;
  throw std::logic_error(std::string("no shadow pass for this technique and the ") + light_type_name(light) + " light");
}

std::uint64_t ShadowPass::next_serial() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

std::vector<float> ShadowPass::read_depth(int* size) const {
  *size = 0;
  return {};
}

namespace {
// The lit pass's base-colour unit (lit_pass.cpp): no shadow pass uses it for anything else.
constexpr int kMaskTextureUnit = 6;

ProgramDesc with_alpha_mask(ProgramDesc desc) {
  desc.defines.emplace_back("ALPHA_MASK", "1");
  return desc;
}
}  // namespace

AlphaMaskVariant::AlphaMaskVariant(const ProgramDesc& pass_program)
    : desc_(with_alpha_mask(pass_program)),
      callback_([this](const GpuScene::Range& range) {
        if (!current_) {
          glUseProgram(program_.id());
          base_color_.set(kMaskTextureUnit);
          if (use_) use_(*this);
          current_ = true;
        }
        scene_->bind_texture(range, kMaskTextureUnit);
        alpha_cutoff_.set(range.alpha_cutoff);
      }) {}

bool AlphaMaskVariant::follow(const ProgramDesc& pass_program) {
  desc_ = with_alpha_mask(pass_program);
  program_.set_desc(desc_);
  return !built_ || program_.rebuild();
}

void AlphaMaskVariant::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  if (built_) f(program_);
}

bool AlphaMaskVariant::ready(const GpuScene& scene) {
  if (!scene.has_masked_casters()) return false;
  if (!built_) {
    program_.set_desc(desc_);
    program_.rebuild();
    built_ = true;
  }
  if (!program_.valid()) return false;
  if (generation_ != program_.generation()) {
    generation_ = program_.generation();
    base_color_ = Uniform(program_.id(), "u_base_color");
    alpha_cutoff_ = Uniform(program_.id(), "u_alpha_cutoff");
    locations_.clear();
  }
  scene_ = &scene;
  current_ = false;
  return true;
}

GLint AlphaMaskVariant::location(const char* name) {
  for (const auto& [n, at] : locations_)
    if (n == name) return at;
  locations_.emplace_back(name, glGetUniformLocation(program_.id(), name));
  return locations_.back().second;
}

void set_shadow_culling(int cull) {
  if (cull == 0) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(cull == 1 ? GL_FRONT : GL_BACK);
  }
}

void draw_casters_from_light(PassContext& ctx, const glm::mat4& light_view_proj,
                             const std::function<void(const GpuScene::Range&)>* masked) {
  set_shadow_culling(ctx.cull);
  const auto counts =
      ctx.gpu_scene.draw_casters(&light_view_proj, 1, ctx.params.get(param::shadow_cull_casters), masked);
  ctx.stats.draws += counts.drawn;
  ctx.stats.casters_culled += counts.culled;
  glDisable(GL_CULL_FACE);
}

std::vector<std::uint8_t> depth_map_image(const std::vector<float>& depth, int size) {
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
  flip_rows(rgba, size, size, 4);
  return rgba;
}

}  // namespace shadowlab
