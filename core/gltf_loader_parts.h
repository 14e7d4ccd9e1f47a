// The glTF loader's parts (core/gltf_loader.cpp and the core/gltf_*.cpp files it names): the Loader class
// and what its files share. Only those files include it; everyone else calls load_gltf (core/gltf_loader.h).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "core/gltf_loader.h"
#include "core/scene.h"
#include "core/untrusted.h"

namespace shadowlab::gltf_detail {

namespace fs = std::filesystem;

// glTF buffers are little-endian; elements are copied out byte for byte.
static_assert(std::endian::native == std::endian::little, "the glTF reader assumes a little-endian host");

inline constexpr std::uint64_t kMaxU64 = std::numeric_limits<std::uint64_t>::max();

// a * b + c, or nothing when it does not fit in 64 bits.
inline std::optional<std::uint64_t> mul_add(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  if (b != 0 && a > (kMaxU64 - c) / b) return std::nullopt;
  return a * b + c;
}

inline std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) { return b > kMaxU64 - a ? kMaxU64 : a + b; }

inline std::string str(std::uint64_t n) { return std::to_string(n); }

// The file sandbox tinygltf reads through (core/gltf_file.cpp).
struct FolderSandbox;

// Base-colour images are decoded here, once each, to RGBA8. One that cannot be decoded (corrupt, an
// unknown format, too large) is not an error of the model: its problem is kept per image, the loader
// reports it and draws a checker in its place.
struct ImageProblems {
  std::map<int, std::string> by_image;
};
bool decode_image(tinygltf::Image* image, int index, std::string*, std::string*, int, int, const unsigned char* bytes,
                  int size, void* user);
// What replaces an image that could not be decoded: 8 x 8 magenta and black squares, seen at once.
std::shared_ptr<const std::vector<std::uint8_t>> checker_image(int* width, int* height);

// Accessors' component types and element types (core/gltf_references.cpp).
std::size_t component_size(int component_type);
const char* component_name(int component_type);
const char* type_name(int type);
// Bytes of one element; for the formats we read (VEC3 FLOAT, SCALAR integers) there is no padding.
std::size_t element_size(const tinygltf::Accessor& a);
bool all_finite(const std::vector<double>& v);

// One triangle primitive of one node instance, found by the scene walk and drawn as one Mesh.
struct Draw {
  int node = 0, mesh = 0, primitive = 0;
  glm::dmat4 world{1.0};
};

class Loader {
 public:
  Loader(const fs::path& path, const LoadLimits& limits) : path_(path), limits_(limits) {}

  Scene load();

  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  // One printable line of bounded length: the parts quoted from the file were cut already, this bounds
  // the whole (and escapes a file name that holds control characters).
  [[noreturn]] void fail(const std::string& problem) const {
    throw LoadError(printable(path_.string(), 400) + ": " + printable(problem, 1200));
  }

  // ---- 1. The file and tinygltf.

  // Debian's tinygltf trusts a GLB chunk's declared length: a BIN chunk that claims more bytes than the
  // file holds makes it copy past the end of the input (found by the fuzzer). Every chunk must fit in
  // the file before tinygltf sees it; other container faults (lengths, headers) are left to its parser.
  // Returns the JSON chunk (the first chunk, when its type is JSON), for the checks before tinygltf.
  std::string_view check_glb_chunks(std::string_view bytes);

  // The model file, read once: a FIFO, a device or a folder is refused before anything is read.
  std::string read_model_file() const;

  // What tinygltf would build from the JSON, measured before it builds it: depth (its parser of extras
  // and extensions recurses), values, array sizes, the schema's types, the buffers' total size. Then
  // tinygltf parses a document that is known to be within the limits.
  void check_json(std::string_view text, FolderSandbox& box);

  // A base64 data: URI's decoded size follows from its length: one that disagrees with the buffer's
  // byteLength is refused before tinygltf decodes it (60 MB of it took seconds, to fail anyway).
  void check_data_uri(const std::string& uri, std::uint64_t byte_length, std::size_t buffer) const;

  void parse();

  void check_asset() const;

  // ---- 2. References, buffer views, accessor layouts.

  struct Kind {
    const char* one;
    const char* many;
  };

  // `index` names an element of an array of `count` `kind`s; -1 means "none" where that is allowed.
  void check_index(int index, std::size_t count, Kind kind, bool optional, const std::string& referrer) const;

  // Every index reference tinygltf keeps, whether or not we use the object: a dangling reference means
  // a broken file.
  void check_references() const;

  // Remembers what each accessor is used for, so that messages can say "accessor 3 (POSITION of mesh 0
  // primitive 0)". Runs after check_references: every index is valid.
  void name_accessor_roles();

  std::string accessor_name(int a) const;

  void check_buffer_views() const;

  // Component types, counts and strides: what can be checked without looking at byte ranges.
  void check_accessor_layouts() const;

  // ---- 3. Node hierarchy.

  // The node's own transform, from its matrix or its translation, rotation and scale.
  glm::dmat4 local_transform(std::size_t i) const;

  // glTF nodes form trees: each node has at most one parent and no node is its own ancestor. Checked
  // for all nodes, used or not, together with the depth limit and the transforms.
  void check_nodes();

  // ---- 4. The scene walk.

  // "node 3" or "node 3 ('wheel')", for messages.
  std::string node_name(int n) const;

  // The root nodes to draw: the default scene's, scene 0's when none is set, or every parentless node
  // when the file has no scenes.
  std::vector<int> scene_roots() const;

  // A POSITION or NORMAL accessor must hold plain floats.
  void check_vec3_float(int index) const;

  // Data we read must come from a buffer view: sparse accessors and all-zero accessors (no bufferView)
  // are legal glTF but never useful geometry, so they are not supported.
  void check_readable(int index) const;

  // Checks a triangle primitive's formats and returns how many vertices and triangles it makes.
  std::pair<std::uint64_t, std::uint64_t> check_primitive(std::size_t m, std::size_t p) const;

  // Lists the triangle primitives of the chosen scene with their world transforms. Totals are checked
  // against the limits as the walk goes, from the declared counts, before any geometry is allocated.
  std::vector<Draw> walk_scene() const;

  // ---- 5. Accessor byte ranges.

  void check_accessor_ranges() const;

  // ---- 6. Reading.

  // The bytes of element k of an accessor whose range has been checked.
  const unsigned char* element(const tinygltf::Accessor& a, std::size_t k) const;

  std::vector<glm::vec3> read_vec3(int index) const;

  // Index values, each checked against the vertex count and the primitive-restart value glTF forbids.
  std::vector<std::uint32_t> read_indices(int index, std::size_t vertices) const;

  // One Texture per glTF texture; the pixels of an image are decoded once and shared by every texture
  // that uses it. A bad or missing image becomes a checker, with one warning naming it and the problem.
  std::vector<Texture> build_textures();

  // The primitive's material: base colour factor, texture (with its TEXCOORD_0), alpha mode and cutoff.
  void apply_material(Mesh& mesh, int material, const tinygltf::Primitive& prim) const;

  // A float, normalised unsigned byte or unsigned short attribute (TEXCOORD_n, COLOR_0) as vectors of N
  // floats; COLOR_0 may be VEC3 (alpha 1).
  template <typename V>
  std::vector<V> read_floats(int index, const std::string& what) const;

  static std::string where_primitive(const Draw& d);

  Mesh build_mesh(const Draw& d) const;

  // A model far from the world's origin for its size (a georeferenced site: a few hundred units at a
  // million) would lose its shape in float world coordinates: its vertices are kept relative to the
  // centre of its box instead, found in double. Others keep the world's origin (their file's coordinates).
  static glm::dvec3 far_origin(const std::vector<Mesh>& meshes, const std::vector<Draw>& draws);
  static constexpr double kFarOriginExtents = 16.0;

  // The node's world transform, less the scene's origin (in double), applied to the mesh.
  void place_mesh(Mesh& mesh, const Draw& d, const glm::dvec3& origin) const;

  fs::path path_;
  LoadLimits limits_;
  mutable std::vector<std::string> warnings_;  // what the specification says to ignore, for the caller
  tinygltf::Model model_;
  ImageProblems image_problems_;
  std::vector<std::string> roles_;  // per accessor: what uses it, for messages
  std::vector<int> parent_;         // per node: its parent, or -1
  std::vector<glm::dmat4> local_;   // per node: its own transform
};

// A float, normalised unsigned byte or unsigned short attribute (TEXCOORD_n, COLOR_0) as vectors of N
// floats; COLOR_0 may be VEC3 (alpha 1).
template <typename V>
std::vector<V> Loader::read_floats(int index, const std::string& what) const {
  const auto& a = model_.accessors[static_cast<std::size_t>(index)];
  check_readable(index);  // element() needs a bufferView; the range check skipped accessors with none
  const int n = a.type == TINYGLTF_TYPE_VEC2 ? 2 : a.type == TINYGLTF_TYPE_VEC3 ? 3 : a.type == TINYGLTF_TYPE_VEC4 ? 4 : 0;
  const int c = a.componentType;
  if (n == 0 || n > V::length() ||
      !(c == TINYGLTF_COMPONENT_TYPE_FLOAT || ((c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) && a.normalized)))
    fail(accessor_name(index) + " (" + what + ") must be float or normalised unsigned byte/short vectors");
  const std::size_t size = component_size(c);
  std::vector<V> out(a.count, V(1.0f));
  for (std::size_t k = 0; k < a.count; ++k) {
    const auto* e = element(a, k);
    for (int j = 0; j < n; ++j) {
      float v = 0.0f;
      if (c == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        std::memcpy(&v, e + j * size, sizeof v);
        if (!std::isfinite(v)) fail(accessor_name(index) + " (" + what + ") element " + str(k) + " is not finite");
      } else if (size == 1) {
        v = static_cast<float>(e[j]) / 255.0f;
      } else {
        std::uint16_t u = 0;
        std::memcpy(&u, e + 2 * j, 2);
        v = static_cast<float>(u) / 65535.0f;
      }
      out[k][j] = v;
    }
  }
  return out;
}

}  // namespace shadowlab::gltf_detail
