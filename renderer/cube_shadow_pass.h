// The point light's shadow map (lab 8): the six faces of a cube of distances, with the render targets it
// owns.
//
//   six passes:  for each face f: scene from the light through view[f] -> layer f of the distance faces
//   one pass:    scene once; layers.geom emits every triangle into all six layers (gl_Layer)
//
// Each face is a 90-degree perspective view in GL's cube-map face order and orientation
// (point_light_views), stored as one layer of a 2D array texture (+X, -X, +Y, -Y, +Z, -Z): the lit pass
// selects the face and the texel for a direction itself, with the GL specification's cube-map rule (the
// largest component picks the face), as engines do when they pack the faces into a shadow atlas; a
// samplerCube would do the same selection in hardware. The faces store what "lab/cube_store.glsl"
// returns, the distance to the light (R32F), not perspective depth: depth is not linear in distance and
// its axis changes from face to face. A depth texture (D24, six layers) does the depth test in both
// modes. The renderer creates this pass only while a lab uses a point light with shadow maps.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "renderer/gl_objects.h"
#include "renderer/gpu_mesh.h"
#include "renderer/light.h"
#include "renderer/shader.h"

namespace shadowlab {

// The clear value of the distance cube: no surface in that direction, so nothing shadows anything.
inline constexpr float kCubeEmptyDistance = 1e30f;

class CubeShadowPass {
 public:
  CubeShadowPass();

  // Points "lab/cube_store.glsl" (what each texel stores; default shaders/cube/store.glsl) at a file and
  // rebuilds; false (old programs kept) on a compile error.
  bool set_includes(const std::map<std::string, std::filesystem::path>& includes, const IncludeRules& rules = {});
  template <typename F>
  void for_each_program(F&& f) {
    f(faces_);
    f(layered_);
  }

  // (Re)allocates the faces at this size. Returns true when anything changed.
  bool ensure_targets(int size);
  // Draws the distances. single_pass: one draw per mesh through the layering geometry shader; else six
  // passes. Skips the casters outside a face's frustum (outside all six in one pass) when cull_casters.
  // Counts draws, faces rendered and casters culled.
  void draw(const GpuScene& scene, const CubeLightViews& views, const glm::vec3& light_position, bool single_pass,
            bool cull_casters, long& draws, long& faces, long& culled);

  GLuint texture() const { return distance_.id(); }  // GL_TEXTURE_2D_ARRAY, six layers
  int size() const { return size_; }
  // One face's distances, bottom row first (GL order), in the face's own orientation.
  std::vector<float> read_face(int face) const;

 private:
  ReloadableProgram faces_, layered_;
  struct FaceUniforms {
    int generation = -1;
    Uniform light_view_proj, light_position;
  } faces_u_;
  struct LayeredUniforms {
    int generation = -1;
    Uniform face_view_proj, light_position;
  } layered_u_;

  int size_ = 0;
  GlTexture distance_;  // GL_TEXTURE_2D_ARRAY, six layers, R32F, nearest, clamped to each face's edge
  GlTexture depth_;     // GL_TEXTURE_2D_ARRAY, six layers, DEPTH_COMPONENT24: the depth test, never sampled
  GlFramebuffer fbo_;
};

}  // namespace shadowlab
