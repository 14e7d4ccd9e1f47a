// glTF loading, step 6: reading the buffers into meshes (positions finite, indices in range, sound
// normals), and placing them in the world (core/gltf_loader.cpp).
#include "core/gltf_loader_parts.h"

#include <cstring>

#include <glm/gtx/transform.hpp>

namespace shadowlab::gltf_detail {

// The bytes of element k of an accessor whose range has been checked.
const unsigned char* Loader::element(const tinygltf::Accessor& a, std::size_t k) const {
  const auto& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_size(a);
  return model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset + a.byteOffset +
         k * stride;
}

std::vector<glm::vec3> Loader::read_vec3(int index) const {
  const auto& a = model_.accessors[static_cast<std::size_t>(index)];
  std::vector<glm::vec3> out(a.count);
  for (std::size_t k = 0; k < a.count; ++k) {
    float xyz[3];
    std::memcpy(xyz, element(a, k), sizeof(xyz));
    out[k] = glm::vec3(xyz[0], xyz[1], xyz[2]);
  }
  return out;
}

// Index values, each checked against the vertex count and the primitive-restart value glTF forbids.
std::vector<std::uint32_t> Loader::read_indices(int index, std::size_t vertices) const {
  const auto& a = model_.accessors[static_cast<std::size_t>(index)];
  const std::size_t size = component_size(a.componentType);
  const std::uint32_t restart = size == 1 ? 0xFFu : size == 2 ? 0xFFFFu : 0xFFFFFFFFu;
  std::vector<std::uint32_t> out(a.count);
  for (std::size_t k = 0; k < a.count; ++k) {
    std::uint32_t v = 0;
    std::memcpy(&v, element(a, k), size);  // little-endian: the low bytes
    if (v == restart)
      fail(accessor_name(index) + " element " + str(k) + " is " + str(v) + ", the primitive-restart value of " +
           component_name(a.componentType) + ", which glTF forbids in indices");
    if (v >= vertices)
      fail(accessor_name(index) + " element " + str(k) + " is " + str(v) + ", but POSITION has only " +
           str(vertices) + " vertices");
    out[k] = v;
  }
  return out;
}

std::string Loader::where_primitive(const Draw& d) {
  return "mesh " + std::to_string(d.mesh) + " primitive " + std::to_string(d.primitive);
}

Mesh Loader::build_mesh(const Draw& d) const {
  const auto& gmesh = model_.meshes[static_cast<std::size_t>(d.mesh)];
  const auto& prim = gmesh.primitives[static_cast<std::size_t>(d.primitive)];
  const auto& node = model_.nodes[static_cast<std::size_t>(d.node)];

  Mesh mesh;
  // Names come from the file: kept printable and short, since the panel and render.json show them.
  mesh.name = !gmesh.name.empty() ? printable(gmesh.name, 80)
              : !node.name.empty() ? printable(node.name, 80)
                                   : "mesh " + std::to_string(d.mesh);
  const int position = prim.attributes.at("POSITION");
  mesh.positions = read_vec3(position);
  apply_material(mesh, prim.material, prim);
  if (const auto color = prim.attributes.find("COLOR_0"); color != prim.attributes.end())
    mesh.colors = read_floats<glm::vec4>(color->second, "COLOR_0");
  if ((!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) ||
      (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()))
    fail(where_primitive(d) + ": TEXCOORD or COLOR_0 has a count other than POSITION's");
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const glm::vec3& p = mesh.positions[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(accessor_name(position) + " element " + str(k) + " is not finite");
  }

  std::vector<std::uint32_t> corners;
  if (prim.indices >= 0) {
    corners = read_indices(prim.indices, mesh.positions.size());
  } else {
    corners.resize(mesh.positions.size());
    for (std::size_t k = 0; k < corners.size(); ++k) corners[k] = static_cast<std::uint32_t>(k);
  }
  // Strips and fans as the glTF spec defines them, with the winding of their first triangle.
  if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < corners.size(); ++i) {
      const std::size_t odd = i % 2;
      mesh.indices.insert(mesh.indices.end(), {corners[i], corners[i + 1 + odd], corners[i + 2 - odd]});
    }
  } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 0; i + 2 < corners.size(); ++i)
      mesh.indices.insert(mesh.indices.end(), {corners[i + 1], corners[i + 2], corners[0]});
  } else {
    mesh.indices = std::move(corners);
  }

  // Normals from the file when every one is finite and non-zero; otherwise computed from the faces.
  if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end()) {
    mesh.normals = read_vec3(normal->second);
    const bool sound = std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const glm::vec3& n) {
      const float length = glm::length(n);
      return std::isfinite(length) && length > 0.0f;
    });
    if (!sound) mesh.normals.clear();
  }
  if (mesh.normals.empty()) compute_normals(mesh);

  return mesh;
}

// A model far from the world's origin for its size (a georeferenced site: a few hundred units at a
// million) would lose its shape in float world coordinates: its vertices are kept relative to the
// centre of its box instead, found in double. Others keep the world's origin (their file's coordinates).
glm::dvec3 Loader::far_origin(const std::vector<Mesh>& meshes, const std::vector<Draw>& draws) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < meshes.size(); ++i)
    for (const glm::vec3& p : meshes[i].positions) {
      const glm::dvec3 w(draws[i].world * glm::dvec4(glm::dvec3(p), 1.0));
      if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) continue;  // refused in place_mesh
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  if (!(lo.x <= hi.x)) return glm::dvec3(0.0);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double distance = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
  // float keeps 2^-24 of the distance: at 16 extents that is 1e-6 of the model's size.
  return distance > kFarOriginExtents * extent ? centre : glm::dvec3(0.0);
}

// The node's world transform, less the scene's origin (in double), applied to the mesh.
void Loader::place_mesh(Mesh& mesh, const Draw& d, const glm::dvec3& origin) const {
  const std::string where = "mesh " + std::to_string(d.mesh) + " primitive " + std::to_string(d.primitive);
  // Skins and morph targets are ignored: the lab draws the rest pose under the node's transform.
  transform_mesh(mesh, glm::mat4(glm::translate(glm::dmat4(1.0), -origin) * d.world));
  // The camera and light fits square the scene's extent (in float): a scene wider than ~1.8e19 gives
  // NaN matrices and a blank frame. Far below that, max_coordinate keeps the maths and the depth
  // precision meaningful.
  const double limit = limits_.max_coordinate;
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const glm::vec3& p = mesh.positions[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(node_name(d.node) + "'s transform takes " + where + " to non-finite positions");
    const glm::dvec3 world = origin + glm::dvec3(p);
    const double largest = std::max({std::abs(world.x), std::abs(world.y), std::abs(world.z)});
    if (largest > limit) {
      char figures[64];
      std::snprintf(figures, sizeof figures, "%.3g, beyond the limit of %.3g", largest, limit);
      fail(node_name(d.node) + "'s transform takes " + where + " vertex " + str(k) + " to a coordinate of " + figures +
           " (LoadLimits::max_coordinate)");
    }
  }
}
}  // namespace shadowlab::gltf_detail
