// Scene: triangle meshes in world space, the input of every pass and of the ray-cast oracle.
//
// Node transforms are baked into the vertices when a scene is built or loaded: the lab's scenes are
// static, and one world-space copy keeps the shadow passes, the lit pass and the oracle looking at
// exactly the same triangles.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Bounds& b) {
    if (!b.empty()) {
      extend(b.min);
      extend(b.max);
    }
  }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
  // The eight corners, in the order (x, y, z) bits of the index: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
  glm::vec3 corner(int i) const {
    return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
  }
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // world space
  std::vector<glm::vec3> normals;    // world space, unit length, one per position
  std::vector<std::uint32_t> indices;  // triangle list; every index < positions.size()
  glm::vec3 color{0.8f};
  bool casts_shadow = true;

  std::size_t triangle_count() const { return indices.size() / 3; }
  Bounds bounds() const;
};

struct Scene {
  std::string name;  // "default" for the built-in scene, else the file it came from
  std::vector<Mesh> meshes;
  // Where the vertices' origin stands in the world, in double: a model far from the world's origin keeps
  // float offsets from the centre of its box here (the glTF loader decides), so its shape survives. The
  // vertices, the bounds and everything graded are in the scene's own frame (relative to this point);
  // the renderer places the scene at origin + p (renderer/placement.h).
  glm::dvec3 origin{0.0};

  Bounds bounds() const;
  std::size_t triangle_count() const;
};

// Fills in smooth per-vertex normals (area-weighted face normals) for a mesh that has none.
void compute_normals(Mesh& mesh);

// Applies a transform to positions and normals (normals by the inverse transpose, renormalised).
void transform_mesh(Mesh& mesh, const glm::mat4& transform);

// The built-in scene, made in code so the lab runs with no files: a ground plane, two boxes, a sphere,
// a slab floating above the ground and a thin vertical plate. The slab shows peter-panning (its shadow
// detaches when the bias grows) and the plate shows acne and light leaking through thin geometry.
Scene make_default_scene();

// Occluders stacked at different heights over a receiver: the textbook case of VSM light bleeding.
Scene make_stacked_occluders_scene();

// Shapes used by the built-in scenes and by tests.
Mesh make_box(const glm::vec3& center, const glm::vec3& half_size, const glm::vec3& color);
Mesh make_plane(const glm::vec3& center, float half_size_x, float half_size_z, const glm::vec3& color);
Mesh make_sphere(const glm::vec3& center, float radius, int slices, int stacks, const glm::vec3& color);

}  // namespace shadowlab
