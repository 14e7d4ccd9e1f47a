#include "renderer/gpu_mesh.h"

#include <cstddef>

#include "renderer/light.h"

namespace shadowlab {

namespace {
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
};
}  // namespace

GpuScene::GpuScene(const Scene& scene)
    : vao_(GlVertexArray::create()), vertices_(GlBuffer::create()), indices_(GlBuffer::create()) {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  for (const Mesh& mesh : scene.meshes) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    Range range;
    range.first_index = static_cast<std::uint32_t>(indices.size());
    range.index_count = static_cast<std::uint32_t>(mesh.indices.size());
    range.bounds = mesh.bounds();
    range.casts_shadow = mesh.casts_shadow;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      vertices.push_back({mesh.positions[i], i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0), mesh.color});
    for (std::uint32_t index : mesh.indices) indices.push_back(base + index);
    ranges_.push_back(range);
    triangles_ += mesh.triangle_count();
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  // Attribute locations are fixed across all shaders: 0 position, 1 normal, 2 colour.
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
}

void GpuScene::draw(const Range& range) const {
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(range.index_count), GL_UNSIGNED_INT,
                 reinterpret_cast<void*>(static_cast<std::uintptr_t>(range.first_index) * sizeof(std::uint32_t)));
}

GpuScene::CasterCounts GpuScene::draw_casters(const glm::mat4* light_view_projs, int count, bool cull) const {
  bind();
  CasterCounts counts;
  for (const auto& range : ranges_) {
    if (!range.casts_shadow) continue;
    bool inside = !cull;
    for (int i = 0; i < count && !inside; ++i) inside = !box_outside_clip_volume(range.bounds, light_view_projs[i]);
    if (!inside) {
      ++counts.culled;
      continue;
    }
    draw(range);
    ++counts.drawn;
  }
  return counts;
}

}  // namespace shadowlab
