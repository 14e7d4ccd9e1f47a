// The scene on the GPU: one vertex buffer (position, normal, colour) and one index buffer for all
// meshes, with each mesh's index range and bounds kept so passes can draw or skip meshes one by one.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl_objects.h"
#include "renderer/scene.h"

namespace shadowlab {

class GpuScene {
 public:
  struct Range {
    std::uint32_t first_index = 0;  // into the shared index buffer
    std::uint32_t index_count = 0;
    Bounds bounds;
    bool casts_shadow = true;
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
  CasterCounts draw_casters(const glm::mat4* light_view_projs, int count, bool cull = true) const;
  const std::vector<Range>& ranges() const { return ranges_; }
  std::size_t triangle_count() const { return triangles_; }

 private:
  GlVertexArray vao_;
  GlBuffer vertices_;
  GlBuffer indices_;
  std::vector<Range> ranges_;
  std::size_t triangles_ = 0;
};

}  // namespace shadowlab
