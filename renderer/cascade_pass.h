// Cascaded shadow maps of a directional light (lab 12): the camera's view range split into csm.count
// slices, each with an ortho light box of its own (core/cascades.h: the splits and the fit, a
// feature's or the solution's), drawn into one layer each of a depth texture array (GL_TEXTURE_2D_ARRAY,
// core since 3.0). The cascades share the texels of one shadow.map_size map. The lit pass picks the
// cascade per pixel by view depth (shaders/csm/visibility.glsl).
//
//   per cascade:  scene from the cascade's box -> layer i of the depth array (24-bit, nearest)
//
// The map depends on the camera, not only on the light: the cascades' matrices are an input of the map
// (frame_inputs), so a camera move redraws it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/cascades.h"
#include "renderer/shadow_pass.h"

namespace shadowlab {

class CascadePass final : public ShadowPass {
 public:
  CascadePass();
  static std::map<std::string, std::string> default_includes(LightType light);

  const Shape& shape() const override;
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules) override;
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) override;
  bool ensure_targets(const ParamSet& params) override;
  void frame_inputs(PassContext& ctx, std::vector<float>& out) override;
  void draw_map(PassContext& ctx) override;
  LitBind lit_bind(GLuint program) const override;
  std::optional<LitView> lit_view(const ParamSet& params) const override;
  void draw_debug_quads(const DebugQuadArea& area) override;
  // Texels per side of one cascade's map.
  int size() const override { return size_; }
  // Cascade 0's depths (read_layer for the others).
  std::vector<float> read_depth(int* size) const override;
  // Every cascade's map, in a square grid (row by row from the top left), as the debug quads show them.
  std::vector<std::uint8_t> image(int* size) const override;

  std::vector<float> read_layer(int layer) const;
  const CascadeFrame& cascades() const { return frame_; }

 private:
  ReloadableProgram depth_, quad_;
  AlphaMaskVariant mask_;  // depth_ with ALPHA_MASK: alpha-tested (MASK) casters
  struct DepthUniforms {
    int generation = -1;
    Uniform light_view_proj;
  } depth_u_;
  struct QuadUniforms {
    int generation = -1;
    Uniform maps, layer;
  } quad_u_;
  int size_ = 0, count_ = 0;
  GlTexture maps_;
  std::vector<GlFramebuffer> fbos_;  // one per layer
  CascadeFrame frame_;
  // What frame_ was computed from (frame_inputs recomputes it only when one of these changes).
  struct FrameKey {
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 to_light{0.0f}, scene_min{0.0f}, scene_max{0.0f};
    int count = 0, budget = 0;
    float lambda = 0.0f;
    bool operator==(const FrameKey&) const = default;
  };
  FrameKey frame_key_;
  bool frame_valid_ = false;  // false: recompute on the next frame (new programs may mean new functions)
};

}  // namespace shadowlab
