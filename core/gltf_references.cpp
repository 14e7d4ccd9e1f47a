// glTF loading, steps 2 and 3: every index reference, buffer views against their buffers, accessor
// layouts, and the node hierarchy (the order of the checks: core/gltf_loader.cpp).
#include "core/gltf_loader_parts.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/transform.hpp>

namespace shadowlab::gltf_detail {

std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // INT, DOUBLE and anything else: not allowed in glTF 2.0 accessors
  }
}

const char* component_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "an invalid component type";
  }
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    default: return "MAT4";  // tinygltf rejects any other type while parsing
  }
}

// Bytes of one element; for the formats we read (VEC3 FLOAT, SCALAR integers) there is no padding.
std::size_t element_size(const tinygltf::Accessor& a) {
  return component_size(a.componentType) *
         static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)));
}

bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// `index` names an element of an array of `count` `kind`s; -1 means "none" where that is allowed.
void Loader::check_index(int index, std::size_t count, Kind kind, bool optional, const std::string& referrer) const {
  if (optional && index == -1) return;
  if (index < 0 || static_cast<std::size_t>(index) >= count)
    fail(referrer + " refers to " + kind.one + " " + std::to_string(index) + ", which does not exist (the file has " +
         str(count) + " " + (count == 1 ? kind.one : kind.many) + ")");
}

// Every index reference tinygltf keeps, whether or not we use the object: a dangling reference means
// a broken file.
void Loader::check_references() const {
  const auto& m = model_;
  const Kind accessor{"accessor", "accessors"}, buffer_view{"bufferView", "bufferViews"}, buffer{"buffer", "buffers"},
      image{"image", "images"}, sampler{"sampler", "samplers"}, texture{"texture", "textures"},
      material{"material", "materials"}, mesh{"mesh", "meshes"}, node{"node", "nodes"}, camera{"camera", "cameras"},
      skin{"skin", "skins"}, scene{"scene", "scenes"};
  const auto n = [](const auto& v) { return v.size(); };

  for (std::size_t i = 0; i < m.bufferViews.size(); ++i)
    check_index(m.bufferViews[i].buffer, n(m.buffers), buffer, false, "bufferView " + str(i));
  for (std::size_t i = 0; i < m.accessors.size(); ++i) {
    const auto& a = m.accessors[i];
    const std::string who = "accessor " + str(i);
    check_index(a.bufferView, n(m.bufferViews), buffer_view, true, who);
    if (a.sparse.isSparse) {
      check_index(a.sparse.indices.bufferView, n(m.bufferViews), buffer_view, false, who + " (sparse indices)");
      check_index(a.sparse.values.bufferView, n(m.bufferViews), buffer_view, false, who + " (sparse values)");
    }
  }
  for (std::size_t i = 0; i < m.images.size(); ++i)
    check_index(m.images[i].bufferView, n(m.bufferViews), buffer_view, true, "image " + str(i));
  for (std::size_t i = 0; i < m.textures.size(); ++i) {
    check_index(m.textures[i].source, n(m.images), image, true, "texture " + str(i));
    check_index(m.textures[i].sampler, n(m.samplers), sampler, true, "texture " + str(i));
  }
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const auto& mat = m.materials[i];
    const std::string who = "material " + str(i);
    for (int t :
         {mat.pbrMetallicRoughness.baseColorTexture.index, mat.pbrMetallicRoughness.metallicRoughnessTexture.index,
          mat.normalTexture.index, mat.occlusionTexture.index, mat.emissiveTexture.index})
      check_index(t, n(m.textures), texture, true, who);
  }
  for (std::size_t i = 0; i < m.meshes.size(); ++i) {
    for (std::size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
      const auto& prim = m.meshes[i].primitives[p];
      const std::string who = "mesh " + str(i) + " primitive " + str(p);
      for (const auto& [name, a] : prim.attributes) check_index(a, n(m.accessors), accessor, false, who + " " + name);
      check_index(prim.indices, n(m.accessors), accessor, true, who + " indices");
      check_index(prim.material, n(m.materials), material, true, who);
      for (const auto& target : prim.targets)
        for (const auto& [name, a] : target)
          check_index(a, n(m.accessors), accessor, false, who + " morph target " + name);
    }
  }
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const auto& nd = m.nodes[i];
    const std::string who = "node " + str(i);
    check_index(nd.mesh, n(m.meshes), mesh, true, who);
    check_index(nd.camera, n(m.cameras), camera, true, who);
    check_index(nd.skin, n(m.skins), skin, true, who);
    for (int c : nd.children) check_index(c, n(m.nodes), node, false, who + " (children)");
  }
  for (std::size_t i = 0; i < m.skins.size(); ++i) {
    const std::string who = "skin " + str(i);
    check_index(m.skins[i].inverseBindMatrices, n(m.accessors), accessor, true, who);
    check_index(m.skins[i].skeleton, n(m.nodes), node, true, who);
    for (int j : m.skins[i].joints) check_index(j, n(m.nodes), node, false, who + " (joints)");
  }
  for (std::size_t i = 0; i < m.animations.size(); ++i) {
    const auto& anim = m.animations[i];
    const std::string who = "animation " + str(i);
    for (const auto& ch : anim.channels) {
      check_index(ch.sampler, n(anim.samplers), Kind{"animation sampler", "animation samplers"}, false, who);
      check_index(ch.target_node, n(m.nodes), node, true, who);
    }
    for (const auto& s : anim.samplers) {
      check_index(s.input, n(m.accessors), accessor, false, who + " sampler input");
      check_index(s.output, n(m.accessors), accessor, false, who + " sampler output");
    }
  }
  for (std::size_t i = 0; i < m.scenes.size(); ++i)
    for (int nd : m.scenes[i].nodes) check_index(nd, n(m.nodes), node, false, "scene " + str(i));
  check_index(m.defaultScene, n(m.scenes), scene, true, "the default scene");
}

// Remembers what each accessor is used for, so that messages can say "accessor 3 (POSITION of mesh 0
// primitive 0)". Runs after check_references: every index is valid.
void Loader::name_accessor_roles() {
  roles_.assign(model_.accessors.size(), {});
  const auto note = [&](int a, const std::string& role) {
    if (roles_[static_cast<std::size_t>(a)].empty()) roles_[static_cast<std::size_t>(a)] = role;
  };
  for (std::size_t i = 0; i < model_.meshes.size(); ++i) {
    for (std::size_t p = 0; p < model_.meshes[i].primitives.size(); ++p) {
      const auto& prim = model_.meshes[i].primitives[p];
      const std::string where = " of mesh " + str(i) + " primitive " + str(p);
      for (const auto& [name, a] : prim.attributes) note(a, name + where);
      if (prim.indices >= 0) note(prim.indices, "indices" + where);
    }
  }
}

std::string Loader::accessor_name(int a) const {
  const std::string& role = roles_[static_cast<std::size_t>(a)];
  return "accessor " + std::to_string(a) + (role.empty() ? "" : " (" + role + ")");
}

void Loader::check_buffer_views() const {
  for (std::size_t i = 0; i < model_.bufferViews.size(); ++i) {
    const auto& view = model_.bufferViews[i];
    const std::string who = "bufferView " + str(i);
    const std::size_t buffer_size = model_.buffers[static_cast<std::size_t>(view.buffer)].data.size();
    if (view.byteLength == 0) fail(who + " has byteLength 0");
    const auto end = mul_add(1, view.byteOffset, view.byteLength);
    if (!end || *end > buffer_size)
      fail(who + " covers bytes " + str(view.byteOffset) + ".." + (end ? str(*end) : "(overflow)") +
           ", past the end of buffer " + std::to_string(view.buffer) + " (" + str(buffer_size) + " bytes)");
    if (view.byteStride > view.byteLength)
      fail(who + " has byteStride " + str(view.byteStride) + ", more than its byteLength " + str(view.byteLength));
  }
}

// Component types, counts and strides: what can be checked without looking at byte ranges.
void Loader::check_accessor_layouts() const {
  for (std::size_t i = 0; i < model_.accessors.size(); ++i) {
    const auto& a = model_.accessors[i];
    const int index = static_cast<int>(i);
    if (component_size(a.componentType) == 0)
      fail(accessor_name(index) + " has componentType " + std::to_string(a.componentType) +
           ", which glTF 2.0 does not allow");
    if (a.count == 0) fail(accessor_name(index) + " has count 0");
    if (a.bufferView < 0) continue;
    const auto& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.byteStride != 0 && view.byteStride < element_size(a))
      fail(accessor_name(index) + " has " + str(element_size(a)) + "-byte elements, but bufferView " +
           std::to_string(a.bufferView) + " has byteStride " + str(view.byteStride));
  }
}

// The node's own transform, from its matrix or its translation, rotation and scale.
glm::dmat4 Loader::local_transform(std::size_t i) const {
  const auto& nd = model_.nodes[i];
  const std::string who = node_name(static_cast<int>(i));
  if (!all_finite(nd.matrix) || !all_finite(nd.translation) || !all_finite(nd.rotation) || !all_finite(nd.scale))
    fail(who + " has a transform with a number that is not finite");
  if (!nd.matrix.empty()) {
    if (nd.matrix.size() != 16) fail(who + " matrix has " + str(nd.matrix.size()) + " numbers instead of 16");
    return glm::make_mat4(nd.matrix.data());  // column-major, like glTF
  }
  if (!nd.translation.empty() && nd.translation.size() != 3)
    fail(who + " translation has " + str(nd.translation.size()) + " numbers instead of 3");
  if (!nd.rotation.empty() && nd.rotation.size() != 4)
    fail(who + " rotation has " + str(nd.rotation.size()) + " numbers instead of 4");
  if (!nd.scale.empty() && nd.scale.size() != 3)
    fail(who + " scale has " + str(nd.scale.size()) + " numbers instead of 3");

  glm::dmat4 m(1.0);
  if (!nd.translation.empty()) m = glm::translate(glm::make_vec3(nd.translation.data()));
  if (!nd.rotation.empty()) {
    const auto& r = nd.rotation;  // glTF stores x, y, z, w; glm's constructor takes w first
    const glm::dquat q(r[3], r[0], r[1], r[2]);
    const double length = glm::length(q);
    if (!(length > 0.0)) fail(who + " rotation is a zero quaternion");
    m *= glm::mat4_cast(q / length);  // exporters round; renormalise rather than skew
  }
  if (!nd.scale.empty()) m *= glm::scale(glm::make_vec3(nd.scale.data()));
  return m;
}

// glTF nodes form trees: each node has at most one parent and no node is its own ancestor. Checked
// for all nodes, used or not, together with the depth limit and the transforms.
void Loader::check_nodes() {
  const std::size_t count = model_.nodes.size();
  parent_.assign(count, -1);
  for (std::size_t p = 0; p < count; ++p) {
    for (int c : model_.nodes[p].children) {
      const auto child = static_cast<std::size_t>(c);
      if (parent_[child] == static_cast<int>(p))
        fail("node " + str(p) + " lists node " + str(child) + " twice as a child");
      if (parent_[child] != -1)
        fail("node " + str(child) + " is a child of both node " + std::to_string(parent_[child]) + " and node " +
             str(p) + " (a node may have only one parent)");
      parent_[child] = static_cast<int>(p);
    }
  }

  local_.resize(count);
  for (std::size_t i = 0; i < count; ++i) local_[i] = local_transform(i);

  // Walk down from the parentless nodes. With one parent per node this visits each node at most once;
  // the nodes it never reaches are on a loop or hang below one.
  std::vector<int> depth(count, 0);
  std::vector<std::size_t> stack;
  for (std::size_t i = 0; i < count; ++i) {
    if (parent_[i] == -1) {
      depth[i] = 1;
      stack.push_back(i);
    }
  }
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    if (depth[i] > limits_.max_node_depth)
      fail("node " + str(i) + " is " + std::to_string(depth[i]) + " levels deep, above the limit of " +
           std::to_string(limits_.max_node_depth) + " (LoadLimits::max_node_depth)");
    for (int c : model_.nodes[i].children) {
      depth[static_cast<std::size_t>(c)] = depth[i] + 1;
      stack.push_back(static_cast<std::size_t>(c));
    }
  }
  const auto unreached = std::find(depth.begin(), depth.end(), 0);
  if (unreached == depth.end()) return;
  // Climbing `count` parents from an unreached node surely lands on the loop; then go round it once.
  auto on_loop = static_cast<std::size_t>(unreached - depth.begin());
  for (std::size_t step = 0; step < count; ++step) on_loop = static_cast<std::size_t>(parent_[on_loop]);
  std::vector<std::size_t> ancestors{on_loop};  // on_loop, its parent, its grandparent... round the loop
  for (auto i = static_cast<std::size_t>(parent_[on_loop]); i != on_loop; i = static_cast<std::size_t>(parent_[i]))
    ancestors.push_back(i);
  // Printed from parent to child, at most 8 steps: a crafted loop may hold millions of nodes.
  std::string loop = str(on_loop);
  const std::size_t shown = std::min<std::size_t>(ancestors.size() - 1, 8);
  for (std::size_t k = 0; k < shown; ++k) loop += " -> " + str(ancestors[ancestors.size() - 1 - k]);
  loop += shown + 1 < ancestors.size() ? " -> ... (" + str(ancestors.size()) + " nodes)" : " -> " + str(on_loop);
  fail("nodes form a loop: " + loop + " (each node is a child of the one before)");
}

// "node 3" or "node 3 ('wheel')", for messages.
std::string Loader::node_name(int n) const {
  const std::string& name = model_.nodes[static_cast<std::size_t>(n)].name;
  return "node " + std::to_string(n) + (name.empty() ? "" : " (" + quote(name, 60) + ")");
}
}  // namespace shadowlab::gltf_detail
