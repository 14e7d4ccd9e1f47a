// Tests of the glTF loader: the shared models, the peers' invalid files (each with an explicit verdict)
// and small files made here for one defect or feature each.
#include "core/gltf_loader.h"


#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/gltf_doc.h"
#include "tests/test_util.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace shadowlab::test;

// The peers' invalid suites and the valid models live in the repository (assets/invalid and
// assets/models, each with their licenses).
const fs::path kInvalid = fs::path(SHADOWLAB_SOURCE_DIR) / "assets" / "invalid";
const fs::path kModels = fs::path(SHADOWLAB_SOURCE_DIR) / "assets" / "models";

void expect_sane(const Scene& scene) {
  for (const Mesh& m : scene.meshes) {
    ASSERT_EQ(m.normals.size(), m.positions.size()) << m.name;
    ASSERT_EQ(m.indices.size() % 3, 0u) << m.name;
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size()) << m.name;
    for (const glm::vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << m.name;
  }
  const Bounds b = scene.bounds();
  ASSERT_FALSE(b.empty());
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(std::isfinite(b.min[k]) && std::isfinite(b.max[k]));
  }
  EXPECT_GT(glm::length(b.extent()), 0.0f);
}

// ---------------------------------------------------------------------------------------------------
// The models in assets/models.

TEST(GltfModels, EveryModelLoads) {
  // Triangle counts derived from the index accessors' counts of the drawn primitives in each file's JSON.
  const std::map<std::string, std::size_t> expected_triangles = {
      {"Box.gltf", 12},          {"BoxTextured.gltf", 12}, {"Duck.gltf", 4212},      {"Duck.glb", 4212},
      {"02_suzanne.gltf", 3936}, {"CornellBox.glb", 36},   {"PalmTree.gltf", 10124},
  };
  std::set<std::string> seen;
  for (const auto& entry : fs::recursive_directory_iterator(kModels)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    seen.insert(name);
    Scene scene;
    ASSERT_NO_THROW(scene = load_gltf(entry.path()));
    const auto expected = expected_triangles.find(name);
    ASSERT_NE(expected, expected_triangles.end()) << "a new model: add its triangle count to the table";
    EXPECT_EQ(scene.triangle_count(), expected->second);
    expect_sane(scene);
  }
  EXPECT_EQ(seen.size(), expected_triangles.size());
}

TEST(GltfModels, DuckNodeScaleIsApplied) {
  // The duck's vertices span ~100s of units; its root node scales them by 0.01.
  for (const char* file : {"Duck.gltf", "Duck.glb"}) {
    const Scene scene = load_gltf(kModels / "Duck" / file);
    const glm::vec3 size = scene.bounds().extent();
    const float largest = std::max({size.x, size.y, size.z});
    EXPECT_GT(largest, 0.5f) << file;
    EXPECT_LT(largest, 3.0f) << file;
  }
}

TEST(GltfModels, BoxColourComesFromItsMaterial) {
  const Scene scene = load_gltf(kModels / "Box/Box.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_NEAR(scene.meshes[0].color.r, 0.8f, 1e-6f);
  EXPECT_EQ(scene.meshes[0].color.g, 0.0f);
  // A textured material with no baseColorFactor: the factor's default, white, times its texture.
  const Scene textured = load_gltf(kModels / "BoxTextured/BoxTextured.gltf");
  EXPECT_EQ(textured.meshes[0].color, glm::vec3(1.0f));
  EXPECT_EQ(textured.meshes[0].texture, 0);
}

// ---------------------------------------------------------------------------------------------------
// The invalid files from the glTF validator's and Microsoft glTF-SDK's test suites.
//
// Verdict per file: must the loader reject it, and what must its message mention (the reason it is
// rejected). We reject anything unparseable, any dangling reference anywhere in the document, node
// loops, refused URIs, and anything that breaks the geometry we draw. Defects in things we never use
// (camera properties, image bytes, accessor min/max) would be acceptable -- but most of these files
// are reduced to the defect and hold no mesh at all, and a file with nothing to draw is an error too.

struct Verdict {
  bool reject;
  const char* must_mention;  // a fragment of the LoadError message (rejections only)
  const char* why;
};

const std::map<std::string, Verdict>& invalid_file_verdicts() {
  static const std::map<std::string, Verdict> table = {
      // JSON
      {"glTF-Validator/json/bom.gltf", {true, "no triangle meshes", "tinygltf tolerates the BOM; no meshes"}},
      {"glTF-Validator/json/empty_file.gltf", {true, "empty", "empty file"}},
      {"glTF-Validator/json/invalid_object.gltf", {true, "the document is an array", "root is an array (schema)"}},
      {"glTF-Validator/json/invalid_syntax.gltf", {true, "parser", "JSON syntax error"}},
      // GLB container
      {"glTF-Validator/glb/bom.glb", {true, "no triangle meshes", "tinygltf tolerates the BOM; no meshes"}},
      {"glTF-Validator/glb/chunk_too_big.glb", {true, "parser", "chunk longer than the file"}},
      {"glTF-Validator/glb/empty_file.glb", {true, "empty", "empty file"}},
      {"glTF-Validator/glb/empty_json_chunk.glb", {true, "parser", "empty JSON chunk"}},
      {"glTF-Validator/glb/invalid_json_chunk.glb", {true, "parser", "JSON syntax error"}},
      {"glTF-Validator/glb/invalid_magic.glb", {true, "parser", "bad magic"}},
      {"glTF-Validator/glb/invalid_version.glb", {true, "GLB container version 0", "version 0"}},
      {"glTF-Validator/glb/length_mismatch.glb", {true, "parser", "declared length exceeds the file"}},
      {"glTF-Validator/glb/no_header.glb", {true, "parser", "no header"}},
      {"glTF-Validator/glb/only_bin_chunk.glb", {true, "parser", "first chunk is not JSON"}},
      {"glTF-Validator/glb/only_header.glb", {true, "parser", "header only"}},
      {"glTF-Validator/glb/truncated_chunk_data.glb", {true, "chunk 0 (JSON) declares 28 bytes, but only 27 remain", "truncated chunk"}},
      {"glTF-Validator/glb/truncated_chunk_header.glb", {true, "parser", "truncated chunk header"}},
      {"glTF-Validator/glb/unaligned_chunk.glb", {true, "4-byte boundary", "unaligned chunk, reported by tinygltf"}},
      {"glTF-Validator/glb/zero_length.glb", {true, "parser", "declared length 0"}},
      {"glTF-Validator/glb/valid.glb", {true, "no triangle meshes", "valid, but no meshes"}},
      // asset, root
      {"glTF-Validator/asset/1_0_version.gltf", {true, "version", "glTF 1.0"}},
      {"glTF-Validator/root/empty_object.gltf", {true, "parser", "no asset"}},
      // buffers
      {"glTF-Validator/buffer/invalid_uri_data.gltf", {true, "File not found : data:", "malformed data: URI"}},
      {"glTF-Validator/buffer/invalid_uri_data_bytelength.gltf", {true, "has a data: URI holding 1 bytes, but its byteLength is 2", "data size differs from byteLength"}},
      {"glTF-Validator/buffer/invalid_uri_scheme.gltf", {true, "refused", "URI ':' has an empty scheme"}},
      {"glTF-Validator/buffer/no_bin_chunk.glb", {true, "parser", "buffer refers to a missing BIN chunk"}},
      {"glTF-Validator/buffer/not_found.gltf", {true, "not_found.bin", "buffer file missing"}},
      {"glTF-Validator/buffer/wrong_bytelength.glb", {true, "byteLength", "BIN chunk shorter than the buffer"}},
      {"glTF-Validator/buffer/zero_bytelength.gltf", {true, "buffers[0].byteLength is 0", "byteLength below the schema's minimum of 1"}},
      {"glTF-Validator/buffer/valid.gltf", {true, "no triangle meshes", "valid, but no meshes"}},
      // buffer views
      {"glTF-Validator/buffer_view/invalid_length.gltf", {true, "past the end of buffer 0", "view past its buffer"}},
      {"glTF-Validator/buffer_view/invalid_stride_too_big.gltf", {true, "byteStride", "stride above byteLength"}},
      {"glTF-Validator/buffer_view/unresolved_buffer.gltf", {true, "buffer 1", "dangling buffer"}},
      {"glTF-Validator/buffer_view/zero_bytelength.gltf", {true, "bufferViews[0].byteLength is 0", "byteLength below the schema's minimum of 1"}},
      // accessors
      {"glTF-Validator/accessor/alignment.gltf", {true, "uri", "buffer without data (and misaligned accessors)"}},
      {"glTF-Validator/accessor/byteoffset_no_bufferview.gltf",
       {true, "no triangle meshes", "harmless to us (zeros); no meshes"}},
      {"glTF-Validator/accessor/unresolved_bufferviews.gltf", {true, "bufferView 0", "dangling bufferViews"}},
      {"glTF-Validator/accessor_data/invalid_elements_float.gltf",
       {true, "no triangle meshes", "-Infinity is refused in POSITION; here unused: no meshes"}},
      {"glTF-Validator/accessor_data/out_of_range_elements_float.gltf",
       {true, "no triangle meshes", "min/max are not used; no meshes"}},
      // meshes
      {"glTF-Validator/mesh/accessor_unequal_count.gltf",
       {true, "no triangle meshes", "unequal counts are refused when drawn; no nodes"}},
      {"glTF-Validator/mesh/indices_invalid_format.gltf",
       {true, "parser", "tinygltf: index accessor without bufferView"}},
      {"glTF-Validator/mesh/position_accessor_invalid_format.gltf",
       {true, "no triangle meshes", "VEC4 POSITION is refused when drawn; no nodes"}},
      {"glTF-Validator/mesh/unresolved_indices.gltf", {true, "parser", "dangling indices (caught by tinygltf)"}},
      {"glTF-Validator/mesh/unresolved_positions.gltf", {true, "accessor 0", "dangling POSITION"}},
      {"glTF-Validator/mesh/unresolved_material.gltf", {true, "material 0", "dangling material"}},
      {"glTF-Validator/mesh/valid.gltf",
       {true, "parser", "valid, but tinygltf refuses indices without bufferView; no nodes anyway"}},
      {"glTF-Validator/mesh_data/index_buffer_degenerate_triangle.gltf",
       {true, "no triangle meshes", "valid, but no nodes"}},
      {"glTF-Validator/mesh_data/index_buffer_oob.gltf",
       {true, "no triangle meshes", "out-of-range indices are refused when drawn; no nodes"}},
      {"glTF-Validator/mesh_data/index_buffer_primitive_restart.gltf",
       {true, "no triangle meshes", "restart values are refused when drawn; no nodes"}},
      // nodes, scenes
      {"glTF-Validator/node/node_loop.gltf", {true, "loop", "node loop"}},
      {"glTF-Validator/node/node_loop_scene.gltf", {true, "child of both", "a node with two parents (and loops)"}},
      {"glTF-Validator/node/infinite_transform.gltf", {true, "parser", "1e309 overflows"}},
      {"glTF-Validator/node/unresolved_child_node.gltf", {true, "node 1", "dangling child"}},
      {"glTF-Validator/node/unresolved_mesh.gltf", {true, "mesh 0", "dangling mesh"}},
      {"glTF-Validator/scene/unresolved_default_scene.gltf", {true, "scene 0", "dangling default scene"}},
      {"glTF-Validator/scene/unresolved_node.gltf", {true, "node 0", "dangling scene node"}},
      // images, textures, materials
      {"glTF-Validator/image/not_found.gltf",
       {true, "no triangle meshes", "a missing image is only a warning for us; no meshes"}},
      {"glTF-Validator/image/invalid_image_data.gltf",
       {true, "no triangle meshes", "images are not decoded; no meshes"}},
      {"glTF-Validator/image/png_eos.gltf", {true, "no triangle meshes", "images are not decoded; no meshes"}},
      {"glTF-Validator/image/invalid_uri_scheme.gltf", {true, "refused", "image URI ':' goes through the URI policy"}},
      {"glTF-Validator/texture/unresolved_source.gltf", {true, "image 0", "dangling image"}},
      {"glTF-Validator/material/unresolved_basecolor.gltf", {true, "texture 0", "dangling texture"}},
      // Microsoft glTF-SDK
      {"glTF-SDK/glb/CubeInvalidAccessorByteLength.glb", {true, "GLB container version 1", "glTF 1.0 binary"}},
      {"glTF-SDK/glb/CubeInvalidAccessorByteOffset.glb", {true, "GLB container version 1", "glTF 1.0 binary"}},
      {"glTF-SDK/glb/CubeInvalidBufferViewLength.glb", {true, "GLB container version 1", "glTF 1.0 binary"}},
      {"glTF-SDK/glb/CubeMissingTextureRef.glb", {true, "GLB container version 1", "glTF 1.0 binary"}},
      {"glTF-SDK/glb/DuckMissingMaterialRef.glb", {true, "GLB container version 1", "glTF 1.0 binary"}},
      {"glTF-SDK/glb/CubeNoBuffer.glb", {false, "", "valid: a GLB whose buffer is a data: URI"}},
      {"glTF-SDK/glb/WrongBinHeaderLength.glb", {true, "GLB container: chunk 1", "bad BIN chunk header: its length runs past the file"}},
      {"glTF-SDK/glb/WrongJsonLength.glb", {true, "GLB container: chunk 0 (JSON)", "JSON chunk length runs past the file"}},
      {"glTF-SDK/glb/WrongReportedLength.glb", {true, "GLB container: chunk 0 (JSON)", "header length wrong in a 32-byte file whose JSON chunk runs past it too"}},
      {"glTF-SDK/gltf/CameraInvalidPerspective.gltf",
       {true, "triangleWithoutIndices.bin", "cameras are not used, but the buffer file is not shipped"}},
      {"glTF-SDK/gltf/CameraInvalidProjection.gltf",
       {true, "triangleWithoutIndices.bin", "cameras are not used, but the buffer file is not shipped"}},
      {"glTF-SDK/gltf/CameraMissingProperties.gltf",
       {true, "triangleWithoutIndices.bin", "cameras are not used, but the buffer file is not shipped"}},
      {"glTF-SDK/gltf/DuplicateNodes.gltf", {true, "parser", "no asset (and a node that is its own child)"}},
      {"glTF-SDK/gltf/MissingDefaultScene.gltf", {true, "parser", "no asset (and a dangling default scene)"}},
      {"glTF-SDK/gltf/MissingMeshRef.gltf", {true, "parser", "no asset (and a dangling mesh)"}},
      {"glTF-SDK/gltf/MissingNodeRef.gltf", {true, "parser", "no asset (and a dangling child)"}},
  };
  return table;
}

TEST(GltfInvalidFiles, EveryFileGetsItsVerdict) {
  const fs::path root = kInvalid;
  const auto& verdicts = invalid_file_verdicts();

  // The table, the files on disk and EXPECTED.tsv must list the same files.
  std::set<std::string> on_disk;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".gltf" || ext == ".glb") on_disk.insert(fs::relative(entry.path(), root).generic_string());
  }
  std::set<std::string> in_tsv;
  std::ifstream tsv(root / "EXPECTED.tsv");
  ASSERT_TRUE(tsv) << "cannot open EXPECTED.tsv";
  std::string line;
  std::getline(tsv, line);  // header
  while (std::getline(tsv, line)) {
    if (!line.empty()) in_tsv.insert(line.substr(0, line.find('\t')));
  }
  std::set<std::string> in_table;
  for (const auto& [file, verdict] : verdicts) in_table.insert(file);
  EXPECT_EQ(on_disk, in_tsv);
  EXPECT_EQ(on_disk, in_table) << "every invalid file needs a verdict in the table";

  int tried = 0, rejected = 0;
  std::string accepted;
  for (const std::string& file : on_disk) {
    const auto verdict = verdicts.find(file);
    if (verdict == verdicts.end()) continue;  // reported above
    SCOPED_TRACE(file + " (" + verdict->second.why + ")");
    ++tried;
    const std::string message = load_error(root / file);
    if (!message.empty()) ++rejected;
    if (message.empty()) accepted += " " + file;
    if (verdict->second.reject) {
      EXPECT_NE(message, "") << "loaded, but must be rejected";
      EXPECT_NE(message.find(fs::path(file).filename().string()), std::string::npos) << message;
      EXPECT_NE(message.find(verdict->second.must_mention), std::string::npos)
          << "the message should mention '" << verdict->second.must_mention << "': " << message;
    } else {
      EXPECT_EQ(message, "") << "must load";
    }
  }
  std::cout << "[ summary  ] invalid glTF files: " << tried << " tried, " << rejected << " rejected, "
            << (tried - rejected) << " accepted:" << accepted << "\n";
}

// ---------------------------------------------------------------------------------------------------
// Hand-made files.

class GltfHandMade : public TempDirTest {};

TEST_F(GltfHandMade, IndexWidthsAndNonIndexedGiveTheSameTriangle) {
  std::vector<Scene> scenes;
  for (const int type : {kUnsignedByte, kUnsignedShort, kUnsignedInt, 0}) {
    scenes.push_back(load_gltf(triangle_doc(type).write(dir_ / ("tri" + std::to_string(type) + ".gltf"))));
  }
  for (const Scene& s : scenes) {
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(m.positions, kTriangle);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));  // computed: counter-clockwise seen from +z
    EXPECT_EQ(m.color, glm::vec3(0.8f));          // no material
  }
}

TEST_F(GltfHandMade, ExternalBufferInsideTheFolderLoads) {
  Doc d = triangle_doc();
  write_bytes(dir_ / "model/data/tri.bin", d.bin);
  for (const std::string uri : {"data/tri.bin", "data/../data/tri.bin", "data%2Ftri.bin"}) {
    d.buffer(uri);
    EXPECT_EQ(load_gltf(d.write(dir_ / "model/tri.gltf")).triangle_count(), 1u) << uri;
  }
}

TEST_F(GltfHandMade, UrisOutsideTheFolderAreRefused) {
  Doc d = triangle_doc();
  write_bytes(dir_ / "outside.bin", d.bin);  // exists: a refusal is not just "not found"
  write_bytes(dir_ / "model/tri.bin", d.bin);
  fs::create_symlink(dir_ / "outside.bin", dir_ / "model/link.bin");
  const std::string absolute = (dir_ / "model/tri.bin").string();  // refused although inside the folder
  for (const std::string uri : {"../outside.bin", "%2E%2E/outside.bin", "link.bin", absolute.c_str(),
                                "http://example.com/tri.bin", "file:///etc/hostname", "C:/tri.bin"}) {
    d.buffer(uri);
    const std::string message = load_error(d.write(dir_ / "model/tri.gltf"));
    EXPECT_NE(message.find("tri.gltf: URI '"), std::string::npos) << uri << ": " << message;
    EXPECT_NE(message.find("refused"), std::string::npos) << uri << ": " << message;
    // tinygltf url-decodes URIs before the policy sees them: the message shows the decoded form.
    const std::string shown = uri.starts_with("%2E%2E") ? "../outside.bin" : uri;
    EXPECT_NE(message.find(shown), std::string::npos) << uri << ": " << message;
  }
}

TEST_F(GltfHandMade, ImageUrisGoThroughTheSamePolicy) {
  write_bytes(dir_ / "outside.png", {1, 2, 3});
  write_bytes(dir_ / "model/inside.png", {1, 2, 3});  // not a PNG at all: images are not decoded
  Doc d = triangle_doc();
  // Undecodable images do not matter: a file that is no PNG, a data: URI of a type tinygltf does not know.
  d.j["images"] = json::array({{{"uri", "inside.png"}}, {{"uri", "data:image/webp;base64,AAAA"}}});
  EXPECT_NO_THROW(load_gltf(d.write(dir_ / "model/tri.gltf")));
  d.j["images"] = json::array({{{"uri", "../outside.png"}}});
  const std::string message = load_error(d.write(dir_ / "model/tri.gltf"));
  EXPECT_NE(message.find("URI '../outside.png' refused"), std::string::npos) << message;
}

TEST_F(GltfHandMade, IndexOutOfRange) {
  Doc d = triangle_doc(kUnsignedShort);
  d.bin[36 + 4] = 3;  // indices {0, 1, 3}
  const std::string message = load_error(d.write(dir_ / "oob.gltf"));
  EXPECT_NE(
      message.find("oob.gltf: accessor 1 (indices of mesh 0 primitive 0) element 2 is 3, but POSITION has only 3"),
      std::string::npos)
      << message;
}

TEST_F(GltfHandMade, IndexCountNotAMultipleOfThree) {
  Doc d = triangle_doc(kUnsignedShort);
  d.j["accessors"][1]["count"] = 2;
  EXPECT_NE(load_error(d.write(dir_ / "two.gltf")).find("mesh 0 primitive 0 has 2 indices, not a multiple of 3"),
            std::string::npos);
}

TEST_F(GltfHandMade, AccessorPastItsBufferView) {
  Doc d = triangle_doc(kUnsignedShort);
  d.j["accessors"][0]["count"] = 4;  // the view holds 3 vec3s (36 bytes)
  const std::string message = load_error(d.write(dir_ / "long.gltf"));
  EXPECT_NE(
      message.find(
          "accessor 0 (POSITION of mesh 0 primitive 0) reads bytes 0..48 past the end of bufferView 0 (36 bytes)"),
      std::string::npos)
      << message;
}

TEST_F(GltfHandMade, BufferViewPastItsBuffer) {
  Doc d = triangle_doc();
  d.j["bufferViews"][0]["byteOffset"] = 4;
  EXPECT_NE(load_error(d.write(dir_ / "view.gltf")).find("past the end of buffer 0 (36 bytes)"), std::string::npos);
}

TEST_F(GltfHandMade, NodeLoop) {
  Doc d = triangle_doc();  // node 0 draws the triangle
  d.node({{"children", {2}}});
  d.node({{"children", {1}}});
  const std::string message = load_error(d.write(dir_ / "loop.gltf"));
  EXPECT_NE(message.find("loop.gltf: nodes form a loop: "), std::string::npos) << message;
  EXPECT_NE(message.find("1 -> 2"), std::string::npos) << message;
}

TEST_F(GltfHandMade, NodeWithTwoParents) {
  Doc d = triangle_doc();
  d.node({{"children", {0}}});
  d.node({{"children", {0}}});
  EXPECT_NE(load_error(d.write(dir_ / "two.gltf")).find("node 0 is a child of both node 1 and node 2"),
            std::string::npos);
}

TEST_F(GltfHandMade, NodeDepthLimit) {
  Doc d;
  const int mesh = d.mesh({{{"attributes", {{"POSITION", d.vec3s(kTriangle)}}}}});
  int child = d.node({{"mesh", mesh}});
  for (int i = 0; i < 4; ++i) child = d.node({{"children", {child}}});  // 5 levels
  d.scene({child});
  const fs::path file = d.write(dir_ / "deep.gltf");
  EXPECT_NO_THROW(load_gltf(file, LoadLimits{.max_node_depth = 5}));
  EXPECT_NE(load_error(file, LoadLimits{.max_node_depth = 4}).find("above the limit of 4 (LoadLimits::max_node_depth)"),
            std::string::npos);
}

TEST_F(GltfHandMade, MemoryBombIsRefusedForItsLimit) {
  Doc d = triangle_doc(kUnsignedShort);
  d.j["accessors"][0]["count"] = 4'000'000'000ull;  // 48 GB of positions declared, 36 bytes present
  const std::string message = load_error(d.write(dir_ / "bomb.gltf"));
  EXPECT_NE(message.find("4000000000 vertices, above the limit of 4000000 (LoadLimits::max_total_vertices"),
            std::string::npos)
      << message;
  // The same for indices.
  Doc e = triangle_doc(kUnsignedInt);
  e.j["accessors"][1]["count"] = 3'000'000'000ull;
  EXPECT_NE(load_error(e.write(dir_ / "bomb2.gltf")).find("1000000000 triangles, above the limit of 4000000 (LoadLimits::max_total_triangles"),
            std::string::npos);
}

TEST_F(GltfHandMade, FileSizeLimit) {
  const fs::path file = triangle_doc().write(dir_ / "small.gltf");
  EXPECT_NE(load_error(file, LoadLimits{.max_file_bytes = 100})
                .find("small.gltf: the file is " + std::to_string(fs::file_size(file)) +
                      " bytes, above the limit of 100 bytes (LoadLimits::max_file_bytes)"),
            std::string::npos);
  // External buffers count against the scene's buffer budget, by what they declare, before any is read.
  Doc d = triangle_doc();
  const std::vector<std::uint8_t> padding(10'000);
  d.view(padding.data(), padding.size());
  write_bytes(dir_ / "tri.bin", d.bin);
  d.buffer("tri.bin");
  const fs::path external = d.write(dir_ / "external.gltf");
  EXPECT_EQ(load_gltf(external).triangle_count(), 1u);
  const std::string message = load_error(external, LoadLimits{.max_buffer_bytes = 10'000});
  EXPECT_NE(message.find("external.gltf: its buffers declare 10036 bytes, above the limit of 10000 bytes for a scene "
                         "(LoadLimits::max_buffer_bytes)"),
            std::string::npos)
      << message;
  // A file larger than its buffer declares is refused unread.
  d.j["buffers"][0]["byteLength"] = 36;
  const std::string longer = load_error(d.write(dir_ / "longer.gltf"));
  EXPECT_NE(longer.find("longer.gltf: buffer URI 'tri.bin': the file is 10036 bytes, above the limit of 36 bytes "
                        "(the byteLength its buffer declares)"),
            std::string::npos)
      << longer;
}

TEST_F(GltfHandMade, NanPositionIsRefused) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Doc d = triangle_doc();
  std::memcpy(d.bin.data() + 4 * sizeof(float), &nan, sizeof(float));  // vertex 1, y
  const std::string message = load_error(d.write(dir_ / "nan.gltf"));  // embedded as a base64 data: URI
  EXPECT_NE(message.find("accessor 0 (POSITION of mesh 0 primitive 0) element 1 is not finite"), std::string::npos)
      << message;
}

TEST_F(GltfHandMade, UnsupportedPositionFormats) {
  Doc d = triangle_doc();
  d.j["accessors"][0]["componentType"] = kUnsignedShort;
  d.j["accessors"][0]["normalized"] = true;
  EXPECT_NE(
      load_error(d.write(dir_ / "quantized.gltf")).find("is VEC3 UNSIGNED_SHORT normalized; it must be VEC3 FLOAT"),
      std::string::npos);
  Doc s = triangle_doc();
  s.j["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 0}, {"componentType", kUnsignedByte}}},
                                   {"values", {{"bufferView", 0}}}};
  EXPECT_NE(load_error(s.write(dir_ / "sparse.gltf")).find("is sparse; sparse accessors are not supported"),
            std::string::npos);
}

TEST_F(GltfHandMade, NothingToDraw) {
  Doc d;
  const int points = d.mesh({{{"attributes", {{"POSITION", d.vec3s(kTriangle)}}}, {"mode", 0}}});
  d.scene({d.node({{"mesh", points}})});
  EXPECT_NE(load_error(d.write(dir_ / "points.gltf")).find("points.gltf: no triangle meshes to draw"),
            std::string::npos);
}

TEST_F(GltfHandMade, StripsAndFansBecomeTriangles) {
  // A unit quad facing +z, as a strip (zig-zag order) and as a fan (around the rim), next to a line
  // primitive that is skipped.
  Doc d;
  const int strip = d.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
  const int fan = d.vec3s({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const int mesh = d.mesh({{{"attributes", {{"POSITION", strip}}}, {"mode", 5}},
                           {{"attributes", {{"POSITION", fan}}}, {"mode", 6}},
                           {{"attributes", {{"POSITION", fan}}}, {"mode", 1}}});
  d.scene({d.node({{"mesh", mesh}})});
  const Scene scene = load_gltf(d.write(dir_ / "strips.gltf"));
  ASSERT_EQ(scene.meshes.size(), 2u);
  for (const Mesh& m : scene.meshes) {
    ASSERT_EQ(m.triangle_count(), 2u);
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                      c = m.positions[m.indices[t + 2]];
      EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "triangle " << t / 3 << " faces away";
    }
  }
}

TEST_F(GltfHandMade, NodeTransformsCompose) {
  // Parent: translation (10, 0, 0). Child: 90 degrees about z, then scale 2.
  Doc d;
  const int mesh = d.mesh({{{"attributes", {{"POSITION", d.vec3s(kTriangle)}}}}});
  const float s = std::sqrt(0.5f);
  const int child = d.node({{"mesh", mesh}, {"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}});
  d.scene({d.node({{"translation", {10, 0, 0}}, {"children", {child}}})});
  const Scene scene = load_gltf(d.write(dir_ / "tree.gltf"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  const glm::vec3 expected[3] = {{10, 0, 0}, {10, 2, 0}, {8, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(glm::distance(m.positions[static_cast<std::size_t>(k)], expected[k]), 0.0f, 1e-5f) << k;
  }
  EXPECT_NEAR(glm::distance(m.normals[0], glm::vec3(0, 0, 1)), 0.0f, 1e-5f);

  // The same hierarchy with matrices instead of TRS.
  d.j["nodes"][0] = {{"mesh", mesh}, {"matrix", {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}}};
  d.j["nodes"][1] = {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}, {"children", {child}}};
  const Scene with_matrices = load_gltf(d.write(dir_ / "matrices.gltf"));
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(glm::distance(with_matrices.meshes[0].positions[static_cast<std::size_t>(k)], expected[k]), 0.0f,
                1e-5f);
  }
}

// A box made by scene.h, written with or without its normals, under a mirroring node.
TEST_F(GltfHandMade, MirroredNodeKeepsOutwardNormals) {
  const Mesh box = make_box(glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0.5f), glm::vec3(1.0f));
  for (const bool with_normals : {true, false}) {
    SCOPED_TRACE(with_normals ? "normals from the file" : "computed normals");
    Doc d;
    json attributes = {{"POSITION", d.vec3s(box.positions)}};
    if (with_normals) attributes["NORMAL"] = d.vec3s(box.normals);
    const int indices = d.indices(box.indices, kUnsignedInt);
    const int mesh = d.mesh({{{"attributes", attributes}, {"indices", indices}}});
    d.scene({d.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}, {"translation", {5, 0, 0}}})});
    const Scene scene = load_gltf(d.write(dir_ / "mirror.gltf"));
    const Mesh& m = scene.meshes[0];
    const glm::vec3 center(4.5f, 0.0f, 0.0f);  // x = 0.5 mirrored to -0.5, then moved by 5
    EXPECT_NEAR(glm::distance(m.bounds().center(), center), 0.0f, 1e-5f);
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                      c = m.positions[m.indices[t + 2]];
      const glm::vec3 outward = (a + b + c) / 3.0f - center;
      EXPECT_GT(glm::dot(glm::cross(b - a, c - a), outward), 0.0f) << "winding of triangle " << t / 3;
      for (const std::uint32_t i : {m.indices[t], m.indices[t + 1], m.indices[t + 2]}) {
        EXPECT_GT(glm::dot(m.normals[i], outward), 0.0f) << "normal of triangle " << t / 3;
      }
    }
  }
}

TEST_F(GltfHandMade, UnsoundNormalsAreRecomputed) {
  Doc d;
  const json attributes = {{"POSITION", d.vec3s(kTriangle)}, {"NORMAL", d.vec3s({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}})}};
  d.scene({d.node({{"mesh", d.mesh({{{"attributes", attributes}}})}})});
  const Scene scene = load_gltf(d.write(dir_ / "zero_normals.gltf"));
  for (const glm::vec3& n : scene.meshes[0].normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

// An accessor with no bufferView (legal glTF: all zeros) read as COLOR_0 or as a texture's TEXCOORD_0 is
// refused by name. The range check skips such accessors, so reading one indexed bufferViews[-1]: found by
// the fuzzer (UBSan: pointer overflow in Loader::element, from read_floats).
TEST_F(GltfHandMade, ColourAndTexcoordWithoutBufferViewAreRefused) {
  Doc colour = triangle_doc();
  colour.j["accessors"].push_back({{"componentType", kFloat}, {"count", 3}, {"type", "VEC4"}});
  colour.j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 1;
  const std::string c = load_error(colour.write(dir_ / "colour.gltf"));
  EXPECT_NE(c.find("colour.gltf: accessor 1 (COLOR_0 of mesh 0 primitive 0) has no bufferView (all zeros)"),
            std::string::npos)
      << c;

  Doc uv = triangle_doc();
  uv.j["accessors"].push_back({{"componentType", kFloat}, {"count", 3}, {"type", "VEC2"}});
  uv.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 1;
  uv.j["meshes"][0]["primitives"][0]["material"] = 0;
  uv.j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
  uv.j["textures"] = json::array({{{"source", 0}}});
  uv.j["images"] = json::array({{{"uri", "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElE"
                                         "QVR4nGP4z8AAAAMBAQDJ/pLvAAAAAElFTkSuQmCC"}}});
  const std::string t = load_error(uv.write(dir_ / "texcoord.gltf"));
  EXPECT_NE(t.find("texcoord.gltf: accessor 1 (TEXCOORD_0 of mesh 0 primitive 0) has no bufferView (all zeros)"),
            std::string::npos)
      << t;
}

TEST_F(GltfHandMade, MaterialColourAndNames) {
  Doc d;
  const int position = d.vec3s(kTriangle);
  d.j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0.25, 0.5, 0.75, 1.0}}}}}});
  const int named = d.mesh({{{"attributes", {{"POSITION", position}}}, {"material", 0}}});
  d.j["meshes"][0]["name"] = "mesh name";
  const int unnamed = d.mesh({{{"attributes", {{"POSITION", position}}}}});
  d.scene({d.node({{"mesh", named}, {"name", "node a"}}), d.node({{"mesh", unnamed}, {"name", "node b"}})});
  const Scene scene = load_gltf(d.write(dir_ / "names.gltf"));
  ASSERT_EQ(scene.meshes.size(), 2u);
  std::map<std::string, glm::vec3> colours;
  for (const Mesh& m : scene.meshes) colours[m.name] = m.color;
  EXPECT_EQ(colours["mesh name"], glm::vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(colours["node b"], glm::vec3(0.8f));
}

TEST_F(GltfHandMade, GlbWithItsBinChunkLoads) {
  // A GLB written by hand: header, JSON chunk, BIN chunk holding the triangle.
  Doc d = triangle_doc();
  d.j["buffers"] = json::array({{{"byteLength", d.bin.size()}}});
  const std::vector<std::uint8_t> glb = make_glb(d.j.dump(), d.bin, d.bin.size());
  write_bytes(dir_ / "tri.glb", glb);
  const Scene scene = load_gltf(dir_ / "tri.glb");
  ASSERT_EQ(scene.triangle_count(), 1u);
  EXPECT_EQ(scene.meshes[0].positions, kTriangle);

  // Truncating it anywhere must give a LoadError, never a crash.
  for (std::size_t size = 0; size < glb.size(); size += 7) {
    write_bytes(dir_ / "cut.glb", std::vector<std::uint8_t>(glb.begin(), glb.begin() + static_cast<long>(size)));
    EXPECT_NE(load_error(dir_ / "cut.glb"), "") << size;
  }
}

// The fuzzer's finding (104 bytes): a BIN chunk that declares 20 bytes where 16 remain, and a buffer of 17
// bytes. Debian's tinygltf trusts the chunk length and copies past the end of the input (ASan:
// heap-buffer-overflow in LoadBinaryFromMemory); the loader refuses the chunk before tinygltf sees it.
TEST_F(GltfHandMade, GlbChunkLongerThanTheFileIsRefusedBeforeParsing) {
  std::vector<std::uint8_t> bin(16);
  for (std::size_t b = 0; b < bin.size(); ++b) bin[b] = static_cast<std::uint8_t>(b);
  const auto glb = make_glb(R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":17}]})", bin, 20);  // 4 too many
  write_bytes(dir_ / "bin_overrun.glb", glb);
  EXPECT_EQ(load_error(dir_ / "bin_overrun.glb"),
            (dir_ / "bin_overrun.glb").string() + ": GLB container: chunk 1 (BIN) declares 20 bytes, but only 16 remain in the file");
}

// A georeferenced model: a unit box a million units from the origin. Baked in float world coordinates
// its corners would round to 1/16 of a unit; the loader keeps the box's centre as the scene's origin (in
// double) and the vertices relative to it, exact. Near the origin nothing changes.
TEST_F(GltfHandMade, AModelFarFromTheOriginKeepsItsShape) {
  const Mesh box = make_box(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(1.0f));
  for (const double far : {0.0, 1.0e6}) {
    SCOPED_TRACE(far);
    Doc d;
    const int indices = d.indices(box.indices, kUnsignedInt);
    const int mesh = d.mesh({{{"attributes", {{"POSITION", d.vec3s(box.positions)}}}, {"indices", indices}}});
    d.scene({d.node({{"mesh", mesh}, {"translation", {far + 0.3, 2.0 * far, -far}}})});
    const Scene scene = load_gltf(d.write(dir_ / "far.gltf"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const glm::dvec3 expected_origin = far == 0.0 ? glm::dvec3(0.0) : glm::dvec3(far + 0.3, 2.0 * far, -far);
    EXPECT_EQ(scene.origin, expected_origin);
    const glm::vec3 shift = far == 0.0 ? glm::vec3(0.3f, 0.0f, 0.0f) : glm::vec3(0.0f);
    for (std::size_t k = 0; k < box.positions.size(); ++k)
      EXPECT_LT(glm::distance(scene.meshes[0].positions[k], box.positions[k] + shift), 1e-6f) << k;
  }
}

TEST_F(GltfHandMade, MissingFile) {
  EXPECT_NE(load_error(dir_ / "nowhere.gltf").find("nowhere.gltf: file not found"), std::string::npos);
}

}  // namespace
}  // namespace shadowlab
