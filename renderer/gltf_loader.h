// glTF 2.0 loading (.gltf with embedded or external buffers, .glb) into a world-space Scene.
//
// tinygltf parses the file; it checks little of what it parses, so every index, offset, count and
// reference is validated here before it is used. A file that fails gets a LoadError whose message names
// the file and the problem; nothing is read outside the model's folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include "renderer/scene.h"

namespace shadowlab {

class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadLimits {
  std::uint64_t max_file_bytes = 1ull << 30;       // 1 GiB
  std::uint64_t max_total_vertices = 50'000'000;   // summed over all drawn primitives
  std::uint64_t max_total_indices = 150'000'000;
  int max_node_depth = 256;
};

// Throws LoadError ("<file>: <problem>") on any invalid or unsupported input.
Scene load_gltf(const std::filesystem::path& path, const LoadLimits& limits = {});

}  // namespace shadowlab
