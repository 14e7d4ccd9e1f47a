// Stencil shadow volumes (lab 9): the adjacency buffers and the extrusion program, owned by the pass.
//
//   ambient pass (renderer):  the scene, ambient only -> colour, depth (and the G-buffer)
//   stencil pass (this):      volumes from extrude.geom, colour and depth writes off, two-sided stencil:
//                               z-pass: front faces +1, back faces -1 where the depth test passes
//                               z-fail: back faces +1, front faces -1 where it fails (capped volumes)
//   lit pass (renderer):      the scene again where stencil == 0, the light's share added (ONE, ONE)
//
// The camera's projection has its far plane at infinity, so volume sides and far caps at w = 0 are
// never clipped; GL_DEPTH_CLAMP keeps their depth at 1 exactly. Meshes are welded and given adjacency
// once per scene (renderer/adjacency.h); open, non-manifold and inconsistently wound edges are counted
// per mesh and reported, not hidden. The renderer creates this pass only while a lab uses shadow volumes
// or the volume wireframe view is on.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "renderer/gl_objects.h"
#include "renderer/scene.h"
#include "renderer/shader.h"

namespace shadowlab {

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

class ShadowVolumePass {
 public:
  ShadowVolumePass();

  // Points "lab/volume.glsl" at a file (default shaders/volume/volume.glsl) and rebuilds; false (old
  // program kept) on a compile error.
  bool set_includes(const std::map<std::string, std::filesystem::path>& includes, const IncludeRules& rules = {});
  template <typename F>
  void for_each_program(F&& f) {
    f(program_);
  }

  // Builds the adjacency (GL_TRIANGLES_ADJACENCY indices) of every shadow-casting mesh.
  void set_scene(const Scene& scene);
  const std::vector<VolumeMeshReport>& report() const { return report_; }

  // light: xyz the position (w = 1) or the direction toward the light (w = 0). view_proj must have an
  // infinite far plane. Draws the volumes into the bound framebuffer's stencil buffer.
  void draw_stencil(const glm::mat4& view_proj, const glm::vec4& light, bool z_fail, long& draws);
  // The same geometry as lines, in colour, depth-tested against the scene (the debug view).
  void draw_wireframe(const glm::mat4& view_proj, const glm::vec4& light, bool caps, long& draws);

 private:
  void draw_volumes(const glm::mat4& view_proj, const glm::vec4& light, bool caps, const glm::vec4& color, long& draws);

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
