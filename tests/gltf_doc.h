// Small glTF files made in code for the loader's tests and the hostile cases: a document builder with
// one embedded (or external) buffer, a GLB container writer, and a helper that returns a refusal's text.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/gltf_loader.h"

namespace shadowlab::test {

namespace fs = std::filesystem;
using nlohmann::json;

// Loads a file expected to be refused and returns the LoadError message ("" if it loaded).
inline std::string load_error(const fs::path& path, const LoadLimits& limits = {}) {
  try {
    load_gltf(path, limits);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                        b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t n = b0 << 16 | b1 << 8 | b2;
    out += alphabet[n >> 18 & 63];
    out += alphabet[n >> 12 & 63];
    out += i + 1 < bytes.size() ? alphabet[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
  }
  return out;
}

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

// A glTF document with one buffer, built up by the tests and written as a .gltf. The buffer is
// embedded as a base64 data: URI unless a test gives it another URI.
struct Doc {
  json j = {{"asset", {{"version", "2.0"}}}};
  std::vector<std::uint8_t> bin;

  // Appends bytes (4-byte aligned) as a new buffer view; returns the view's index.
  int view(const void* data, std::size_t size) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t offset = bin.size();
    bin.resize(offset + size);
    std::memcpy(bin.data() + offset, data, size);
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
    return static_cast<int>(j["bufferViews"].size()) - 1;
  }
  int accessor(int view, int component_type, std::uint64_t count, const char* type) {
    j["accessors"].push_back(
        {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}});
    return static_cast<int>(j["accessors"].size()) - 1;
  }
  // With min and max, which the specification requires of POSITION (the validator checks them).
  int vec3s(const std::vector<glm::vec3>& v) {
    std::vector<float> floats;
    glm::vec3 lo(v.empty() ? glm::vec3(0) : v[0]), hi = lo;
    for (const glm::vec3& p : v) {
      floats.insert(floats.end(), {p.x, p.y, p.z});
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const int a = accessor(view(floats.data(), floats.size() * sizeof(float)), kFloat, v.size(), "VEC3");
    j["accessors"][static_cast<std::size_t>(a)]["min"] = {lo.x, lo.y, lo.z};
    j["accessors"][static_cast<std::size_t>(a)]["max"] = {hi.x, hi.y, hi.z};
    return a;
  }
  template <class T>
  int indices(const std::vector<T>& v, int component_type) {
    return accessor(view(v.data(), v.size() * sizeof(T)), component_type, v.size(), "SCALAR");
  }
  int mesh(const std::vector<json>& primitives) {
    j["meshes"].push_back({{"primitives", primitives}});
    return static_cast<int>(j["meshes"].size()) - 1;
  }
  int node(const json& n) {
    j["nodes"].push_back(n);
    return static_cast<int>(j["nodes"].size()) - 1;
  }
  void scene(const std::vector<int>& roots) {
    j["scenes"] = json::array({{{"nodes", roots}}});
    j["scene"] = 0;
  }
  // The buffer, embedded unless `uri` is given.
  void buffer(const std::string& uri = "") {
    j["buffers"] = json::array({{{"byteLength", bin.size()},
                                 {"uri", uri.empty() ? "data:application/octet-stream;base64," + base64(bin) : uri}}});
  }
  fs::path write(const fs::path& file) {
    if (!j.contains("buffers")) buffer();
    fs::create_directories(file.parent_path());
    std::ofstream(file) << j.dump(1);
    return file;
  }
};

inline void write_bytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

// A document drawing kTriangle under one node: POSITION is accessor 0 in bufferView 0 (36 bytes); the
// indices {0, 1, 2}, of the given component type (or none when 0), are accessor 1 in bufferView 1.
inline Doc triangle_doc(int index_type = 0) {
  Doc d;
  json prim = {{"attributes", {{"POSITION", d.vec3s(kTriangle)}}}};
  if (index_type == kUnsignedByte) prim["indices"] = d.indices(std::vector<std::uint8_t>{0, 1, 2}, index_type);
  if (index_type == kUnsignedShort) prim["indices"] = d.indices(std::vector<std::uint16_t>{0, 1, 2}, index_type);
  if (index_type == kUnsignedInt) prim["indices"] = d.indices(std::vector<std::uint32_t>{0, 1, 2}, index_type);
  d.scene({d.node({{"mesh", d.mesh({prim})}})});
  return d;
}

// A GLB container: header, the JSON chunk (padded with spaces to 4 bytes), a BIN chunk holding `bin` whose
// header declares `bin_declared` bytes (its true size unless a test lies), the header's length the file's.
inline std::vector<std::uint8_t> make_glb(std::string text, const std::vector<std::uint8_t>& bin, std::size_t bin_declared) {
  while (text.size() % 4 != 0) text += ' ';
  std::vector<std::uint8_t> glb;
  const auto u32 = [&](std::size_t v) {
    for (int k = 0; k < 4; ++k) glb.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  };
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(12 + 8 + text.size() + 8 + bin.size());
  u32(text.size());
  glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
  glb.insert(glb.end(), text.begin(), text.end());
  u32(bin_declared);
  glb.insert(glb.end(), {'B', 'I', 'N', 0});
  glb.insert(glb.end(), bin.begin(), bin.end());
  return glb;
}

}  // namespace shadowlab::test
