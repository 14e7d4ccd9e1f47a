// Billboards from a geometry shader (lab 11): one point per tree, expanded into an upright quad with a
// cut-out (shaders/billboard/shape.glsl). The view turns each quad toward the camera; the shadow pass
// draws the quad "lab/billboard.glsl" builds (the lab's exercise: toward the light) with its alpha test,
// into the depth map after the scene's casters. The oracle's trees are the light-facing quads as MASK
// triangles whose alpha is the same cut-out function (billboard_light_quads).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl_objects.h"
#include "core/params.h"
#include "core/placement.h"
#include "core/scene.h"
#include "renderer/shader.h"

namespace shadowlab {

struct PassContext;

// The cut-out's alpha at uv ((0, 0) bottom left, (1, 1) top right): shaders/billboard/shape.glsl in
// float, as the GPU computes it.
float billboard_alpha(glm::vec2 uv);

// The billboards' parameters (declared by the lab that uses them; these defaults otherwise).
struct BillboardSize {
  float width = 1.4f, height = 2.0f, cutoff = 0.5f;
};
BillboardSize billboard_size(const ParamSet& params);
std::vector<ParamSpec> billboard_param_specs();
namespace param {
extern const FloatParam billboard_width;
extern const FloatParam billboard_height;
extern const FloatParam billboard_cutoff;
extern const BoolParam billboard_show_shadow_quads;
}  // namespace param

// The quads a right shadow pass draws for trees standing at `bases` under a directional light: upright,
// turned about the vertical toward the light, as one MASK mesh (two triangles per tree, uv as the
// shaders have it) whose alpha is billboard_alpha at the hit's uv; for the oracle.
Mesh billboard_light_quads(const std::vector<glm::vec3>& bases, const BillboardSize& size, const glm::vec3& to_light);

class BillboardPass {
 public:
  BillboardPass();
  // Builds both programs with these includes ("lab/billboard.glsl": the shadow pass's quad and alpha
  // test); false keeps the old ones.
  bool set_includes(const std::map<std::string, std::filesystem::path>& includes, const IncludeRules& rules);
  void for_each_program(const std::function<void(ReloadableProgram&)>& f);
  // The trees' bases in the scene's frame, converted to the GPU's local frame (uploaded when they change).
  void set_points(const std::vector<glm::vec3>& bases, const Placement& placement);
  // Into the bound depth target: the shadow pass's quads from the light.
  void draw_shadow(const PassContext& ctx, const glm::mat4& light_view_proj);
  // Into the bound view target (depth-tested against the scene): the camera-facing trees; with
  // show_shadow_quads also the shadow pass's quads, as the camera sees them.
  void draw_view(const PassContext& ctx, bool show_shadow_quads);
  std::size_t count() const { return count_; }

 private:
  void draw_shadow_program(const PassContext& ctx, const glm::mat4& view_proj);
  ReloadableProgram shadow_, view_;
  // Looked up once per program generation (they were looked up by name every frame).
  struct ShadowUniforms {
    Uniform view_proj, to_light, eye, size, cutoff;
  };
  struct ViewUniforms {
    Uniform view_proj, eye, size, cutoff, ambient;
  };
  UniformCache<ShadowUniforms> shadow_u_;
  UniformCache<ViewUniforms> view_u_;
  GlVertexArray vao_;
  GlBuffer points_;
  std::vector<glm::vec3> uploaded_;
  std::size_t count_ = 0;
};

}  // namespace shadowlab
