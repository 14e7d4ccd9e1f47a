// The scene on the GPU: one vertex buffer (position, normal, colour with alpha, texture coordinates) and
// one index buffer for all meshes, with each mesh's index range, bounds and material kept so passes can
// draw or skip meshes one by one; the scene's base-colour textures, uploaded once each.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl_objects.h"
#include "core/scene.h"

namespace shadowlab {

class GpuScene {
 public:
  struct Range {
    std::uint32_t first_index = 0;  // into the shared index buffer
    std::uint32_t index_count = 0;
    Bounds bounds;
    bool casts_shadow = true;
    int texture = -1;  // into textures(); -1: none (a 1 x 1 white texture stands in)
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;
  };

  GpuScene() = default;
  explicit GpuScene(const Scene& scene);

  void bind() const { glBindVertexArray(vao_.id()); }
  // Draws one mesh (the VAO must be bound).
  void draw(const Range& range) const;
  // Binds the VAO and draws the shadow casters whose bounds reach into the light's volume (the clip
  // volume of any of the given view-projections); the others cannot write a texel, so they are not
  // drawn (unless cull is false: then all are). Counts both.
  struct CasterCounts {
    long drawn = 0, culled = 0;
  };
  // With `masked` given, MASK casters are left out of the first round and drawn after it, each after
  // masked(range) (which binds the alpha-testing program, its texture and cutoff).
  CasterCounts draw_casters(const glm::mat4* light_view_projs, int count, bool cull = true,
                            const std::function<void(const Range&)>* masked = nullptr) const;
  // Whether any mesh has a texture, a MASK or a BLEND material: the lit pass then compiles its material
  // variant (MATERIAL_TEXTURE); a scene without any draws with the plain program, unchanged.
  bool has_materials() const { return has_materials_; }
  bool has_masked_casters() const { return has_masked_casters_; }
  // Binds the range's texture (or the white one) to texture unit `unit`.
  void bind_texture(const Range& range, int unit) const;
  const std::vector<Range>& ranges() const { return ranges_; }
  std::size_t triangle_count() const { return triangles_; }
  // The scene's box (the union of the meshes' boxes, as Scene::bounds() gives it), kept from the
  // upload so that a frame does not walk the vertices again.
  const Bounds& bounds() const { return bounds_; }

 private:
  GlVertexArray vao_;
  GlBuffer vertices_;
  GlBuffer indices_;
  std::vector<Range> ranges_;
  std::vector<GlTexture> textures_;
  GlTexture white_;
  bool has_materials_ = false;
  bool has_masked_casters_ = false;
  std::size_t triangles_ = 0;
  Bounds bounds_;
};

}  // namespace shadowlab
