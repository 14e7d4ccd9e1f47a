// Writes a built-in scene as a glTF file, scaled and moved by its root node:
//   scene_copy NAME OUT.gltf SCALE X Y Z
// The vertices are the scene's own (float, as make_default_scene gives them); the node's scale and
// translation are JSON numbers (double), so a copy 1e4 times smaller and 1e6 units from the origin keeps
// its shape (the loader applies node transforms in double, core/gltf_loader.h). The buffer is OUT.bin
// beside the file. Used by tests/any_scene.py: a copy of a lab's own scene must grade as the scene does.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene.h"

namespace {

using nlohmann::json;

struct Writer {
  std::vector<char> bin;
  json views = json::array(), accessors = json::array();

  // One tightly packed accessor of `count` elements of `type` (VEC3 float or SCALAR unsigned int).
  int add(const void* data, std::size_t bytes, std::size_t count, const char* type, int component, json extra = {}) {
    while (bin.size() % 4) bin.push_back(0);
    views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}});
    bin.insert(bin.end(), static_cast<const char*>(data), static_cast<const char*>(data) + bytes);
    json a = {{"bufferView", views.size() - 1}, {"componentType", component}, {"count", count}, {"type", type}};
    if (extra.is_object()) a.update(extra);
    accessors.push_back(a);
    return static_cast<int>(accessors.size()) - 1;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: scene_copy NAME OUT.gltf SCALE X Y Z\n");
    return 2;
  }
  const shadowlab::Scene scene = shadowlab::builtin_scene(argv[1]);
  const std::filesystem::path out = argv[2];
  const double scale = std::stod(argv[3]);
  const json translation = {std::stod(argv[4]), std::stod(argv[5]), std::stod(argv[6])};
  constexpr int kFloat = 5126, kUnsignedInt = 5125;
  Writer w;
  json meshes = json::array(), materials = json::array(), children = json::array(), nodes = json::array();
  for (const shadowlab::Mesh& m : scene.meshes) {
    const shadowlab::Bounds b = m.bounds();
    const int position = w.add(m.positions.data(), m.positions.size() * sizeof(glm::vec3), m.positions.size(), "VEC3",
                               kFloat, {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}});
    const int normal = w.add(m.normals.data(), m.normals.size() * sizeof(glm::vec3), m.normals.size(), "VEC3", kFloat);
    const int indices = w.add(m.indices.data(), m.indices.size() * sizeof(std::uint32_t), m.indices.size(), "SCALAR",
                              kUnsignedInt);
    materials.push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {m.color.r, m.color.g, m.color.b, 1.0}}}}});
    json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}, {"indices", indices},
                      {"material", materials.size() - 1}};
    meshes.push_back({{"name", m.name}, {"primitives", json::array({primitive})}});
    nodes.push_back({{"name", m.name}, {"mesh", meshes.size() - 1}});
    children.push_back(nodes.size() - 1);
  }
  nodes.push_back({{"name", "placed"}, {"children", children}, {"scale", {scale, scale, scale}}, {"translation", translation}});
  std::filesystem::path bin_path = out;
  bin_path.replace_extension(".bin");
  const json gltf = {{"asset", {{"version", "2.0"}, {"generator", "shadowlab scene_copy"}}},
                     {"scene", 0},
                     {"scenes", json::array({{{"nodes", {nodes.size() - 1}}}})},
                     {"nodes", nodes},
                     {"meshes", meshes},
                     {"materials", materials},
                     {"accessors", w.accessors},
                     {"bufferViews", w.views},
                     {"buffers", json::array({{{"byteLength", w.bin.size()}, {"uri", bin_path.filename().string()}}})}};
  std::ofstream(bin_path, std::ios::binary).write(w.bin.data(), static_cast<std::streamsize>(w.bin.size()));
  std::ofstream(out) << gltf.dump(1) << "\n";
  std::printf("%s: %s scaled by %g, moved by %s\n", out.string().c_str(), argv[1], scale, translation.dump().c_str());
  return 0;
}
