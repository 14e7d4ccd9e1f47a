// The debug views drawn over the lit picture, each a pass of its own that costs nothing while hidden:
// the shadow technique's own views (the variance remap), the triangles in their face normals' colours
// (flat normals from a geometry shader), normals and shadow volumes as lines (geometry shaders), the light's volume as a wireframe, and the shadow map in the corner.
#pragma once

#include <memory>
#include <vector>

#include "renderer/shadow_pass.h"
#include "renderer/shadow_volume_pass.h"

namespace shadowlab {

class LitPass;

class DebugViews {
 public:
  DebugViews();  // builds the flat normals, normals and lines programs; throws if they do not build

  // The flat-normals view's program (shaders/debug/flat_normals.geom: a triangle in, the same triangle
  // with its face normal out, as v_face_normal), exposed so tests can capture what its geometry shader
  // emits (add ProgramDesc::feedback_varyings).
  static ProgramDesc flat_normals_desc();

  void for_each_program(const std::function<void(ReloadableProgram&)>& f);
  // The includes the shadow-volume wireframe is built with; drops the volumes (rebuilt on use).
  void set_includes(const IncludeMap& includes, const IncludeRules& rules);
  void set_scene() { wireframe_scene_stale_ = true; }

  // The views the parameters (view.*) switch on, in order, over the lit pass's colour.
  void draw(PassContext& ctx, ShadowPass& shadow, LitPass& lit);
  // The wireframe's own volumes' adjacency report (empty until the view was shown).
  std::vector<VolumeMeshReport> volume_report() const;

 private:
  void flat_normals(PassContext& ctx, LitPass& lit);
  void normals(PassContext& ctx, LitPass& lit);
  void volumes_wireframe(PassContext& ctx, ShadowPass& shadow, LitPass& lit);
  void light_volume(PassContext& ctx, LitPass& lit);
  void debug_quads(PassContext& ctx, LitPass& lit);

  ReloadableProgram flat_normals_, normals_, lines_;
  struct FlatNormalsUniforms {
    int generation = -1;
    Uniform view_proj;
  } flat_normals_u_;
  struct NormalsUniforms {
    int generation = -1;
    Uniform view_proj, length;
  } normals_u_;
  struct LinesUniforms {
    int generation = -1;
    Uniform view_proj, color;
  } lines_u_;
  GlVertexArray lines_vao_;  // the light volume's 12 edges, made on first use
  GlBuffer lines_vbo_;
  // The volumes the wireframe shows when the shadow technique is not shadow volumes (which has its own).
  std::unique_ptr<ShadowVolumePass> wireframe_volumes_;
  IncludeMap includes_;
  IncludeRules rules_;
  bool wireframe_scene_stale_ = true;
};

}  // namespace shadowlab
