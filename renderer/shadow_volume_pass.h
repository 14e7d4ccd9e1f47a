// Stencil shadow volumes: the adjacency buffers and the extrusion program, owned by the pass. There is
// no shadow map; every frame, from the camera:
//
//   ambient pass (lit pass):  the scene, ambient only -> colour, depth (and the G-buffer)
//   stencil pass (this):      volumes from extrude.geom, colour and depth writes off, two-sided stencil:
//                               z-pass: front faces +1, back faces -1 where the depth test passes
//                               z-fail: back faces +1, front faces -1 where it fails (capped volumes)
//   lit pass (lit pass):      the scene again where stencil == 0, the light's share added (ONE, ONE)
//
// The camera's projection has its far plane at infinity, so volume sides and far caps at w = 0 are
// never clipped; GL_DEPTH_CLAMP keeps their depth at 1 exactly. Meshes are welded and given adjacency
// once per scene (core/adjacency.h); open, non-manifold and inconsistently wound edges are counted
// per mesh and reported, not hidden. The renderer creates this pass only while a feature uses shadow
// volumes or the volume wireframe view is on.
//
// Alpha-tested (glTF MASK) casters get the volume of their whole triangles: a silhouette is found from
// edges, and a cut-out's edges are in its texture. Their shadows are solid here (the lit passes still
// discard their holes in the view); the map techniques cut the holes (AlphaMaskVariant). Leaving them
// out instead would lose their shadows altogether; tests/test_gl_materials.cpp measures both.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "core/scene.h"
#include "renderer/shadow_pass.h"

namespace shadowlab {

// The stencil pass's depth offset, in units of the depth buffer's resolution (glPolygonOffset(0, this)):
// enough for the near caps to lose every depth tie with the faces they lie on (1 left 0.004 % of lab 9's
// graded pixels wrong, 4 none), with no slope term, which would move the shadow outlines.
inline constexpr float kVolumeOffsetUnits = 4.0f;

// What the adjacency of one shadow-casting mesh says about its fitness for shadow volumes.
struct VolumeMeshReport {
  std::string name;
  std::size_t triangles = 0;
  std::size_t edges = 0;
  std::size_t open_edges = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t inconsistent_edges = 0;
  bool closed_manifold() const { return open_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0; }
};

// The triangles a volume program emits for one light, sorted by kind. A corner is on the occluders when
// it is a finite point inside the scene's box, and extruded otherwise: a point at infinity (w = 0), or a
// finite point swept out of the box (a volume that stops at a far but finite distance must not pass for
// caps).
struct VolumeTriangles {
  long sides = 0;      // corners on the occluders and extruded ones: the quads swept by edges
  long near_caps = 0;  // corners on the occluders only
  long far_caps = 0;   // extruded corners only
};

class ShadowVolumePass final : public ShadowPass {
 public:
  ShadowVolumePass();
  static std::map<std::string, std::string> default_includes(LightType light);

  const Shape& shape() const override {
    static const Shape volumes{false, true, LitVariant::VolumeAdditive, {LitVariant::VolumeAdditive, LitVariant::VolumeAmbient},
                               LitDraw{LitVariant::VolumeAmbient, "ambient"}};
    return volumes;
  }
  // Points "lab/volume.glsl" at a file (default shaders/volume/volume.glsl) and rebuilds; false (old
  // program kept) on a compile error.
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules = {}) override;
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) override;
  bool ensure_targets(const ParamSet&) override { return false; }
  void set_host_code(const GlHostCode& code) override { code_ = code; }
  // The volumes into the stencil buffer (volume.method: z-fail or z-pass), after the ambient pass
  // (shape().lit_first) laid the depth down.
  void draw_view_passes(PassContext& ctx, const ViewTarget& view) override;
  LitBind lit_bind(GLuint program) const override;
  int size() const override { return 0; }
  // No shadow map: a 16 x 16 grey placeholder keeps the outputs' shape.
  std::vector<std::uint8_t> image(int* size) const override;

  // Builds the adjacency (GL_TRIANGLES_ADJACENCY indices) of every shadow-casting mesh.
  void set_scene(const Scene& scene) override;
  const std::vector<VolumeMeshReport>& report() const { return report_; }

  // light: xyz the position (w = 1) or the direction toward the light (w = 0). view_proj must have an
  // infinite far plane. Clears the bound framebuffer's stencil and counts the volumes into it, with the
  // state of renderer/volume_stencil.h's stencil_pass (lab 9's GL exercise).
  void draw_stencil(const glm::mat4& view_proj, const glm::vec4& light, bool z_fail, long& draws);
  // Captures the triangles the volumes emit for this light (transform feedback, nothing rasterised) and
  // sorts them by kind: how a grader tells an extrusion of the silhouette from one of every edge. A
  // complete framebuffer must be bound (draws need one even with rasterisation off).
  // `box` is the scene's in the frame the volumes are drawn in.
  VolumeTriangles count_triangles(const glm::vec4& light, bool caps, const Bounds& box);
  // The same geometry as lines, in colour, depth-tested against the scene (the debug view).
  void draw_wireframe(const glm::mat4& view_proj, const glm::vec4& light, bool caps, long& draws);

 private:
  GlHostCode code_;  // whose stencil_pass sets the counting pass's state (the renderer's, or a student's file)
  void draw_volumes(const glm::mat4& view_proj, const glm::vec4& light, bool caps, const glm::vec4& color, long& draws);
  void use_program(const glm::mat4& view_proj, const glm::vec4& light, bool caps, const glm::vec4& color);
  void draw_adjacency(long& draws);

  ReloadableProgram program_;
  struct Uniforms {
    int generation = -1;
    Uniform view_proj, light, caps, color;
  } u_;
  GlVertexArray vao_;
  GlBuffer positions_, indices_;
  std::size_t index_count_ = 0;
  std::vector<VolumeMeshReport> report_;
};

}  // namespace shadowlab
