#include "renderer/cascade_pass.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/image_io.h"

namespace shadowlab {

namespace {

int csm_count(const ParamSet& params) { return params.get(param::csm_count); }

}  // namespace

CascadePass::CascadePass()
    : depth_({"shaders/shadow_depth.vert", {}, "shaders/shadow_depth.frag", {}, {}}),
      quad_({"shaders/fullscreen.vert", {}, "shaders/csm/debug_layer.frag", {}, {}}),
      mask_(depth_.desc()) {}

std::map<std::string, std::string> CascadePass::default_includes(LightType) {
  return {{"lab/visibility.glsl", "shaders/csm/visibility.glsl"}};
}

const ShadowPass::Shape& CascadePass::shape() const {
  static const Shape cascades{true,
                              false,
                              LitVariant::Lit,
                              {LitVariant::Lit, LitVariant::Overlay},
                              std::nullopt,
                              LitOverlay{"shaders/csm/cascade_view.frag", cascade_view_defines()}};
  return cascades;
}

bool CascadePass::set_includes(const IncludeMap&, const IncludeRules&) {
  frame_valid_ = false;  // a new feature set may bring other split and fit functions
  const bool depth_ok = depth_.rebuild();
  const bool mask_ok = mask_.follow(depth_.desc());
  return quad_.rebuild() && depth_ok && mask_ok;
}

void CascadePass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(depth_);
  f(quad_);
  mask_.for_each_program(f);
}

bool CascadePass::ensure_targets(const ParamSet& params) {
  const int count = csm_count(params);
  const int size = cascade_map_size(std::stoi(params.get(param::shadow_map_size)), count);
  if (size == size_ && count == count_) return false;
  maps_ = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.id());
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, size, size, count, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  fbos_.clear();
  for (int layer = 0; layer < count; ++layer) {
    fbos_.push_back(GlFramebuffer::create());
    glBindFramebuffer(GL_FRAMEBUFFER, fbos_.back().id());
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, maps_.id(), 0, layer);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    check_framebuffer("cascade shadow map");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  size_ = size;
  count_ = count;
  return true;
}

void CascadePass::frame_inputs(PassContext& ctx, std::vector<float>& out) {
  static const CascadeSplitFn solution_splits;  // empty: compute_cascades uses the solution's
  static const CascadeFitFn solution_fit;
  const int budget = std::stoi(ctx.params.get(param::shadow_map_size));
  const float lambda = ctx.params.get(param::csm_lambda);
  // The cascades depend on these alone: a still frame keeps them (and allocates nothing).
  const Bounds& box = ctx.gpu_scene.bounds();
  const FrameKey key{ctx.cascade_view, ctx.cascade_projection, ctx.light.to_light, box.min, box.max, count_, budget, lambda};
  if (!frame_valid_ || !(key == frame_key_)) {
    frame_ = compute_cascades(ctx.cascade_view, ctx.cascade_projection, ctx.light.to_light, box, count_, lambda,
                              budget, ctx.cascade_splits ? *ctx.cascade_splits : solution_splits,
                              ctx.cascade_fit ? *ctx.cascade_fit : solution_fit);
    frame_key_ = key;
    frame_valid_ = true;
  }
  out.clear();
  for (const auto& view : frame_.views) {
    const glm::mat4 m = view.view_projection();
    out.insert(out.end(), &m[0][0], &m[0][0] + 16);
  }
}

void CascadePass::draw_map(PassContext& ctx) {
  ctx.timed("shadow", [&] {
    ctx.count_texels([&] {
      if (depth_u_.generation != depth_.generation())
        depth_u_ = {depth_.generation(), Uniform(depth_.id(), "u_light_view_proj")};
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glDepthMask(GL_TRUE);
      glClearDepth(1.0);
      for (int i = 0; i < count_; ++i) {
        glBindFramebuffer(GL_FRAMEBUFFER, fbos_[static_cast<std::size_t>(i)].id());
        glViewport(0, 0, size_, size_);
        glClear(GL_DEPTH_BUFFER_BIT);
        glUseProgram(depth_.id());  // again each cascade: its alpha-tested casters end on mask_'s program
        const glm::mat4 light_view_proj = frame_.views[static_cast<std::size_t>(i)].view_projection();
        depth_u_.light_view_proj.set(light_view_proj);
        draw_casters_from_light(ctx, light_view_proj, mask_.prepare(ctx.gpu_scene, [&](AlphaMaskVariant& v) {
          v.set("u_light_view_proj", light_view_proj);
        }));
      }
    });
  });
}

namespace {
// The cascades' uniforms on a lit program (shaders/csm/visibility.glsl): per cascade, then shared.
struct CascadeUniforms {
  Uniform tex[kMaxCascades], far[kMaxCascades], texel_depth[kMaxCascades];
  Uniform near, count, camera_view, blend, maps;
};
CascadeUniforms cascade_uniforms(GLuint program) {
  CascadeUniforms u;
  for (int i = 0; i < kMaxCascades; ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    u.tex[i] = Uniform(program, ("u_csm_tex" + at).c_str());
    u.far[i] = Uniform(program, ("u_csm_far" + at).c_str());
    u.texel_depth[i] = Uniform(program, ("u_csm_texel_depth" + at).c_str());
  }
  u.near = Uniform(program, "u_csm_near");
  u.count = Uniform(program, "u_csm_count");
  u.camera_view = Uniform(program, "u_csm_camera_view");
  u.blend = Uniform(program, "u_csm_blend");
  u.maps = Uniform(program, "u_csm_maps");
  return u;
}
}  // namespace

LitBind CascadePass::lit_bind(GLuint program) const {
  return [this, u = cascade_uniforms(program)](const ParamSet& params) {
    for (int i = 0; i < frame_.count; ++i) {
      const auto c = static_cast<std::size_t>(i);
      const LightView& v = frame_.views[c];
      u.tex[i].set(clip_to_texture() * v.view_projection());
      u.far[i].set(frame_.splits[c + 1]);
      // One texel's world size in the depth units of the comparison ([0, 1] over the box's depth).
      const float depth_range = 2.0f / std::abs(v.projection[2][2]);
      u.texel_depth[i].set(v.world_size.x / static_cast<float>(frame_.map_size) / depth_range);
    }
    u.near.set(frame_.splits.empty() ? 0.0f : frame_.splits.front());
    u.count.set(frame_.count);
    u.camera_view.set(frame_.camera_view);
    u.blend.set(params.get(param::csm_blend));
    u.maps.set(2);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.id());
    glActiveTexture(GL_TEXTURE0);
  };
}

std::optional<LitView> CascadePass::lit_view(const ParamSet& params) const {
  if (!params.get(param::csm_show_cascades)) return std::nullopt;
  return LitView{{LitVariant::Overlay, "cascade_view"}, cascade_view_legend(count_)};
}

void CascadePass::draw_debug_quads(const DebugQuadArea& area) {
  // One quad per cascade, right to left from the corner, nearest cascade rightmost; smaller when many.
  const int side = count_ > 2 ? area.side * 2 / count_ : area.side;
  glUseProgram(quad_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.id());
  if (quad_u_.generation != quad_.generation())
    quad_u_ = {quad_.generation(), Uniform(quad_.id(), "u_depth_maps"), Uniform(quad_.id(), "u_layer")};
  quad_u_.maps.set(0);
  glBindVertexArray(area.empty_vao);
  for (int i = 0; i < count_; ++i) {
    area.place(area.width - (i + 1) * (side + 4) - 4, 8, side, side,
               "cascade " + std::to_string(i + 1) + " of " + std::to_string(count_));
    quad_u_.layer.set(static_cast<float>(i));
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
}

std::vector<float> CascadePass::read_layer(int layer) const {
  if (layer < 0 || layer >= count_) throw std::out_of_range("no cascade " + std::to_string(layer));
  return read_pixels(fbos_[static_cast<std::size_t>(layer)].id(), GL_NONE, size_, size_, GL_DEPTH_COMPONENT, 1);
}

std::vector<float> CascadePass::read_depth(int* size) const {
  *size = size_;
  return count_ > 0 ? read_layer(0) : std::vector<float>{};
}

std::vector<std::uint8_t> CascadePass::image(int* size) const {
  const int grid = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(count_, 1)))));
  *size = grid * size_;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(*size) * static_cast<std::size_t>(*size) * 4, 255);
  for (int i = 0; i < count_; ++i) {
    const std::vector<std::uint8_t> layer = depth_map_image(read_layer(i), size_);  // top row first
    const int gx = i % grid, gy = i / grid;
    for (int y = 0; y < size_; ++y)
      std::copy_n(&layer[static_cast<std::size_t>(y) * size_ * 4], static_cast<std::size_t>(size_) * 4,
                  &rgba[((static_cast<std::size_t>(gy) * size_ + y) * *size + static_cast<std::size_t>(gx) * size_) * 4]);
  }
  return rgba;
}

}  // namespace shadowlab
