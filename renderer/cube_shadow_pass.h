// The point light's shadow map: a cube map of distances, with the render targets and programs it owns.
//
//   six passes:  for each face f: scene from the light through view[f] -> face f of the distance cube
//   one pass:    scene once; layers.geom emits every triangle into all six faces (gl_Layer)
//
// Each face is a 90-degree perspective view in GL's face order and orientation (point_light_views), so
// the lit pass can look the cube up with the direction from the light to the fragment. The faces store
// the distance to the light (R32F), not perspective depth: depth is not linear in distance and its scale
// changes from face to face. A depth cube map (D24) does the depth test in both modes. The renderer
// creates this pass only while a point light casts shadow-map shadows.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "core/light.h"
#include "renderer/shadow_pass.h"

namespace shadowlab {

// The clear value of the distance cube: no surface in that direction, so nothing shadows anything.
inline constexpr float kCubeEmptyDistance = 1e30f;

class CubeShadowPass final : public ShadowPass {
 public:
  CubeShadowPass();
  static std::map<std::string, std::string> default_includes(LightType light);

  bool set_includes(const IncludeMap& includes, const IncludeRules& rules) override;
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) override;
  bool ensure_targets(const ParamSet& params) override;
  // The six faces (point.single_pass: in one draw through the layering geometry shader).
  void draw_map(PassContext& ctx) override;
  // The six faces, a six-layer array, on texture unit 2 (u_shadow_faces).
  LitBind lit_bind(GLuint program) const override;
  // The six faces in a 3 x 2 grid, top row +X -X +Y, bottom row -Y +Z -Z, together `side` high.
  void draw_debug_quads(const DebugQuadArea& area) override;
  int size() const override { return size_; }
  // The six faces at half resolution in a 3 x 3 grid, top row +X, -X, +Y, middle row -Y, +Z, -Z (bottom
  // row empty); distance from near (dark) to far (light), empty texels white.
  std::vector<std::uint8_t> image(int* size) const override;

  // (Re)allocates the cube maps at this size. Returns true when anything changed.
  bool ensure_targets(int size);
  // Draws the distances. single_pass: one draw per mesh through the layering geometry shader; else six
  // passes. Skips the casters outside a face's frustum (outside all six in one pass) when cull_casters.
  // Counts draws, faces rendered and casters culled.
  void draw(const GpuScene& scene, const CubeLightViews& views, const glm::vec3& light_position, bool single_pass,
            bool cull_casters, long& draws, long& faces, long& culled);

  GLuint texture() const { return distance_.id(); }
  // One face's distances, bottom row first (GL order), in the face's own orientation.
  std::vector<float> read_face(int face) const;

 private:
  ReloadableProgram faces_, layered_;
  AlphaMaskVariant faces_mask_, layered_mask_;  // with ALPHA_MASK: alpha-tested (MASK) casters
  struct FaceUniforms {
    int generation = -1;
    Uniform light_view_proj, light_position;
  } faces_u_;
  struct LayeredUniforms {
    int generation = -1;
    Uniform face_view_proj, light_position;
  } layered_u_;
  ReloadableProgram face_quad_;  // one face of the cube as a debug quad
  struct FaceQuadUniforms {
    int generation = -1;
    Uniform cube, face, far_plane;
  } face_quad_u_;
  float far_plane_ = 1.0f;  // the far plane the faces were drawn with: the largest distance they store

  int size_ = 0;
  GlTexture distance_;  // GL_TEXTURE_2D_ARRAY, six layers in GL's cube face order, R32F, nearest
  GlTexture depth_;     // GL_TEXTURE_2D_ARRAY, DEPTH_COMPONENT24: the depth test, never sampled
  GlFramebuffer fbo_;
};

}  // namespace shadowlab
