// glTF 2.0 loading (.gltf with embedded or external buffers, .glb) into a world-space Scene.
//
// tinygltf parses the file; it checks little of what it parses, so every index, offset, count and
// reference is validated here before it is used, and the JSON is measured (depth, size, values) and its
// types checked against the glTF 2.0 schema before tinygltf parses it. A file that fails gets a
// LoadError whose message names the file and the problem, on one printable line of bounded length
// (text from the file is escaped and cut); nothing is read outside the model's folder.
//
// A scene may expand to at most what LoadLimits allows, counted over the whole scene (the model file,
// every buffer it loads, every node instance it draws), and each refusal names the limit it broke.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene.h"

namespace shadowlab {

class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The budgets of one scene. README.md "Robustness" says why each is what it is; the defaults keep the
// worst accepted file within about 1 GB of memory and a few seconds of loading.
struct LoadLimits {
  std::uint64_t max_file_bytes = 256ull << 20;    // the .gltf or .glb itself
  std::uint64_t max_json_bytes = 32ull << 20;     // its JSON (the whole .gltf, a .glb's JSON chunk)
  int max_json_depth = 64;                        // nested arrays and objects
  std::uint64_t max_json_values = 1'000'000;      // JSON values of any kind
  std::uint64_t max_buffer_bytes = 256ull << 20;  // all buffers together (external, embedded, GLB)
  std::uint64_t max_nodes = 100'000;
  std::uint64_t max_materials = 10'000;
  std::uint64_t max_objects = 100'000;            // any other top-level array (accessors, meshes...)
  std::uint64_t max_instances = 10'000;           // drawn primitives, one per node instance of a mesh
  std::uint64_t max_total_vertices = 4'000'000;   // baked: summed over all instances
  std::uint64_t max_total_triangles = 4'000'000;
  int max_node_depth = 256;
  double max_coordinate = 1e9;                    // world-space |x|, |y|, |z| after the node transforms
};

// Throws LoadError ("<file>: <problem>") on any invalid or unsupported input. What the glTF 2.0
// specification says a client must ignore (a property it does not define) is ignored, with one line per
// case added to `warnings` when given.
Scene load_gltf(const std::filesystem::path& path, const LoadLimits& limits = {},
                std::vector<std::string>* warnings = nullptr);

}  // namespace shadowlab
