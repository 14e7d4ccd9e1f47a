// glTF loading, steps 4 and 5: the scene walk, which lists the triangle primitives to draw and checks
// their formats and the totals against LoadLimits, then accessor byte ranges (core/gltf_loader.cpp).
#include "core/gltf_loader_parts.h"

namespace shadowlab::gltf_detail {

// The root nodes to draw: the default scene's, scene 0's when none is set, or every parentless node
// when the file has no scenes.
std::vector<int> Loader::scene_roots() const {
  std::vector<int> roots;
  if (model_.scenes.empty()) {
    for (std::size_t i = 0; i < parent_.size(); ++i)
      if (parent_[i] == -1) roots.push_back(static_cast<int>(i));
    return roots;
  }
  const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
  roots = model_.scenes[static_cast<std::size_t>(s)].nodes;
  std::vector<bool> listed(model_.nodes.size(), false);
  for (int r : roots) {
    const auto i = static_cast<std::size_t>(r);
    if (listed[i]) fail("scene " + std::to_string(s) + " lists node " + str(i) + " twice");
    if (parent_[i] != -1)
      fail("scene " + std::to_string(s) + " lists node " + str(i) + ", a child of node " +
           std::to_string(parent_[i]) + " (scene nodes must be roots)");
    listed[i] = true;
  }
  return roots;
}

// A POSITION or NORMAL accessor must hold plain floats.
void Loader::check_vec3_float(int index) const {
  const auto& a = model_.accessors[static_cast<std::size_t>(index)];
  check_readable(index);
  if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(accessor_name(index) + " is " + type_name(a.type) + " " + component_name(a.componentType) +
         (a.normalized ? " normalized" : "") + "; it must be VEC3 FLOAT (quantized data is not supported)");
}

// Data we read must come from a buffer view: sparse accessors and all-zero accessors (no bufferView)
// are legal glTF but never useful geometry, so they are not supported.
void Loader::check_readable(int index) const {
  const auto& a = model_.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) fail(accessor_name(index) + " is sparse; sparse accessors are not supported");
  if (a.bufferView < 0) fail(accessor_name(index) + " has no bufferView (all zeros); that is not supported");
}

// Checks a triangle primitive's formats and returns how many vertices and triangles it makes.
std::pair<std::uint64_t, std::uint64_t> Loader::check_primitive(std::size_t m, std::size_t p) const {
  const auto& prim = model_.meshes[m].primitives[p];
  const std::string where = "mesh " + str(m) + " primitive " + str(p);
  const auto position = prim.attributes.find("POSITION");
  if (position == prim.attributes.end()) fail(where + " has no POSITION attribute");
  check_vec3_float(position->second);
  const std::uint64_t vertices = model_.accessors[static_cast<std::size_t>(position->second)].count;
  // Indices are 32-bit: a primitive may address at most 2^32 vertices.
  if (vertices > std::uint64_t{1} << 32) fail(where + " has " + str(vertices) + " vertices, more than 2^32");
  for (const auto& [name, a] : prim.attributes) {
    const std::uint64_t n = model_.accessors[static_cast<std::size_t>(a)].count;
    if (n != vertices)
      fail(accessor_name(a) + " has count " + str(n) + " but POSITION has " + str(vertices) +
           "; all attributes of a primitive must have the same count");
  }
  if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end())
    check_vec3_float(normal->second);

  std::uint64_t corners = vertices;
  if (prim.indices >= 0) {
    const auto& a = model_.accessors[static_cast<std::size_t>(prim.indices)];
    check_readable(prim.indices);
    if (a.type != TINYGLTF_TYPE_SCALAR || (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      fail(accessor_name(prim.indices) + " is " + type_name(a.type) + " " + component_name(a.componentType) +
           "; indices must be SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    corners = a.count;
  }
  const std::string what = prim.indices >= 0 ? " indices" : " vertices";
  if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP || prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    if (corners < 3) fail(where + " is a triangle strip or fan with only " + str(corners) + what);
    return {vertices, corners - 2};
  }
  if (corners % 3 != 0) fail(where + " has " + str(corners) + what + ", not a multiple of 3");
  return {vertices, corners / 3};
}

// Lists the triangle primitives of the chosen scene with their world transforms. Totals are checked
// against the limits as the walk goes, from the declared counts, before any geometry is allocated.
std::vector<Draw> Loader::walk_scene() const {
  std::vector<Draw> draws;
  std::uint64_t total_vertices = 0, total_triangles = 0;
  // Node hierarchy checked: a tree walk, finite, each node once.
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (int r : scene_roots()) stack.emplace_back(r, local_[static_cast<std::size_t>(r)]);
  while (!stack.empty()) {
    const auto [n, world] = stack.back();
    stack.pop_back();
    const auto& nd = model_.nodes[static_cast<std::size_t>(n)];
    // Composed transforms may overflow although each node's is finite (scales of 1e200 twice), and
    // vertices are transformed in single precision: every entry must be finite as a float.
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!(std::abs(world[c][r]) <= std::numeric_limits<float>::max()))
          fail(node_name(n) + "'s world transform overflows (an entry is " + std::to_string(world[c][r]) +
               "; single precision ends at 3.4e38)");
    for (int c : nd.children) stack.emplace_back(c, world * local_[static_cast<std::size_t>(c)]);
    if (nd.mesh < 0) continue;
    const auto m = static_cast<std::size_t>(nd.mesh);
    if (model_.meshes[m].primitives.empty()) fail("mesh " + str(m) + " has no primitives");
    for (std::size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
      const int mode = model_.meshes[m].primitives[p].mode;
      // Points and lines cast no shadows: skipped. Strips and fans are turned into triangle lists.
      if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) continue;
      if (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN)
        fail("mesh " + str(m) + " primitive " + str(p) + " has mode " + std::to_string(mode) +
             ", which is not a glTF primitive mode");
      const auto [vertices, triangles] = check_primitive(m, p);
      total_vertices = saturating_add(total_vertices, vertices);
      total_triangles = saturating_add(total_triangles, triangles);
      if (total_vertices > limits_.max_total_vertices)
        fail("the scene has at least " + str(total_vertices) + " vertices, above the limit of " +
             str(limits_.max_total_vertices) + " (LoadLimits::max_total_vertices; every node instance of a mesh counts)");
      if (total_triangles > limits_.max_total_triangles)
        fail("the scene has at least " + str(total_triangles) + " triangles, above the limit of " +
             str(limits_.max_total_triangles) + " (LoadLimits::max_total_triangles; every node instance of a mesh counts)");
      if (draws.size() >= limits_.max_instances)
        fail("the scene draws more than " + str(limits_.max_instances) +
             " mesh primitives (one per node instance; LoadLimits::max_instances)");
      draws.push_back({n, nd.mesh, static_cast<int>(p), world});
    }
  }
  return draws;
}

void Loader::check_accessor_ranges() const {
  for (std::size_t i = 0; i < model_.accessors.size(); ++i) {
    const auto& a = model_.accessors[i];
    if (a.bufferView < 0) continue;  // nothing stored: zeros (or sparse data, never read)
    const auto& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::uint64_t size = element_size(a);
    const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : size;
    // The last element starts at byteOffset + (count - 1) * stride and is `size` bytes long.
    const auto last = mul_add(a.count - 1, stride, a.byteOffset);
    const auto end = last ? mul_add(1, *last, size) : std::nullopt;
    if (!end || *end > view.byteLength)
      fail(accessor_name(static_cast<int>(i)) + " reads bytes " + str(a.byteOffset) + ".." +
           (end ? str(*end) : "(overflow)") + " past the end of bufferView " + std::to_string(a.bufferView) + " (" +
           str(view.byteLength) + " bytes)");
  }
}
}  // namespace shadowlab::gltf_detail
