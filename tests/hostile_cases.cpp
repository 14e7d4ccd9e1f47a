#include "tests/hostile_cases.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stdexcept>

#include "tests/gltf_doc.h"

namespace shadowlab::test {

namespace {

// Text spliced into a dumped document where the placeholder string stands: nesting this deep cannot
// go through nlohmann's (recursive) serializer, and large arrays are faster written as text.
std::string splice(const json& j, const std::string& placeholder, const std::string& text) {
  std::string out = j.dump();
  const std::string quoted_placeholder = "\"" + placeholder + "\"";
  const auto at = out.find(quoted_placeholder);
  if (at == std::string::npos) throw std::logic_error("no placeholder " + placeholder);
  out.replace(at, quoted_placeholder.size(), text);
  return out;
}

void write_text(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

std::string nested_arrays(std::size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

void make_fifo(const fs::path& file) {
  fs::create_directories(file.parent_path());
  fs::remove(file);
  if (::mkfifo(file.c_str(), 0600) != 0) throw std::runtime_error("cannot make the FIFO " + file.string());
}

// A sparse file of `bytes` (no disk space used): what a hostile buffer may name.
void write_sparse(const fs::path& file, std::uint64_t bytes) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0 || ::ftruncate(fd, static_cast<off_t>(bytes)) != 0) throw std::runtime_error("cannot make " + file.string());
  ::close(fd);
}

// `count` nodes, each an instance of mesh 0 (the triangle), all roots of the scene: as text.
std::string instancing_doc(std::size_t count) {
  Doc d = triangle_doc();
  d.j["nodes"] = "@NODES@";
  d.j["scenes"] = json::array({{{"nodes", "@ROOTS@"}}});
  d.buffer();
  std::string nodes = "[", roots = "[";
  for (std::size_t i = 0; i < count; ++i) {
    nodes += (i ? ",{\"mesh\":0}" : "{\"mesh\":0}");
    roots += (i ? "," : "") + std::to_string(i);
  }
  const json with_nodes = json::parse(splice(d.j, "@NODES@", nodes + "]"));
  return splice(with_nodes, "@ROOTS@", roots + "]");
}

}  // namespace

std::vector<HostileCase> write_hostile_cases(const fs::path& dir) {
  fs::create_directories(dir);
  std::vector<HostileCase> cases;
  const auto add = [&](const std::string& name, const fs::path& file, const std::string& mention, const std::string& item) {
    cases.push_back({name, file, mention, item});
  };
  const std::string depth_limit = "deeper than 64 levels (LoadLimits::max_json_depth)";
  // The triangle with its buffer at `uri` (nothing there unless the case puts it there).
  const auto with_buffer_uri = [&](const std::string& name, const std::string& file, const std::string& uri,
                                   const std::string& mention, const std::string& item) {
    Doc d = triangle_doc();
    d.buffer(uri);
    add(name, d.write(dir / file), mention, item);
  };

  // 1. Nesting 20,000 deep (41 KB) in asset.extras, in an extension, in a GLB.
  {
    Doc d = triangle_doc();
    d.buffer();
    d.j["asset"]["extras"] = "@DEEP@";
    write_text(dir / "deep_extras.gltf", splice(d.j, "@DEEP@", nested_arrays(20'000)));
    add("deep_extras", dir / "deep_extras.gltf", depth_limit, "1: JSON nested 20,000 deep in asset.extras");
    Doc e = triangle_doc();
    e.buffer();
    e.j["nodes"][0]["extensions"] = {{"EXT_deep", {{"value", "@DEEP@"}}}};
    write_text(dir / "deep_extension.gltf", splice(e.j, "@DEEP@", nested_arrays(20'000)));
    add("deep_extension", dir / "deep_extension.gltf", depth_limit, "1: the same in an extension");
    Doc g = triangle_doc();
    g.j["buffers"] = json::array({{{"byteLength", g.bin.size()}}});
    g.j["asset"]["extras"] = "@DEEP@";
    const std::string text = splice(g.j, "@DEEP@", nested_arrays(20'000));
    const std::vector<std::uint8_t> glb = make_glb(text, g.bin, g.bin.size());
    write_bytes(dir / "deep.glb", glb);
    add("deep_glb", dir / "deep.glb", depth_limit, "1: the same in a GLB's JSON chunk");
  }
  // 2. Unbounded work: 200,000 nodes instancing one triangle (a 3 MB file here; 13 MB in the report);
  // 20,000 instances (under the node limit); a 1M-triangle mesh instanced 11 times.
  write_text(dir / "nodes_200k.gltf", instancing_doc(200'000));
  add("nodes_200k", dir / "nodes_200k.gltf", "200000 nodes, above the limit of 100000 (LoadLimits::max_nodes)",
      "2: 200,000 nodes instancing one mesh");
  write_text(dir / "instances_20k.gltf", instancing_doc(20'000));
  add("instances_20k", dir / "instances_20k.gltf", "more than 10000 mesh primitives", "2: 20,000 instances");
  {
    Doc d;
    const int position = d.vec3s(kTriangle);
    const std::vector<std::uint32_t> corners(3'000'000, 0);  // 1M (degenerate) triangles, 12 MB
    const int indices = d.indices(corners, kUnsignedInt);
    const int mesh = d.mesh({{{"attributes", {{"POSITION", position}}}, {"indices", indices}}});
    std::vector<int> roots;
    for (int i = 0; i < 11; ++i) roots.push_back(d.node({{"mesh", mesh}}));
    d.scene(roots);
    write_bytes(dir / "million.bin", d.bin);
    d.buffer("million.bin");
    d.write(dir / "triangles_11m.gltf");
    add("triangles_11m", dir / "triangles_11m.gltf", "above the limit of 4000000 (LoadLimits::max_total_triangles",
        "2: a 1M-triangle mesh instanced 11 times");
  }
  // 3. FIFOs: as the model, as a buffer in the model's folder.
  {
    make_fifo(dir / "fifo.gltf");
    add("fifo_model", dir / "fifo.gltf", "is a FIFO, not a regular file", "3: a FIFO as the model");
    make_fifo(dir / "fifo_buffer/pipe.bin");
    with_buffer_uri("fifo_buffer", "fifo_buffer/model.gltf", "pipe.bin", "buffer URI 'pipe.bin': is a FIFO, not a regular file",
                    "3: a FIFO as a buffer");
  }
  // 4. and 10. Long and hostile text: a 20,000-character URI; a 60 MB data: URI whose length is wrong;
  // escape sequences and forged lines in a URI; a NUL in a URI.
  {
    with_buffer_uri("long_uri", "long_uri.gltf", std::string(20'000, 'a') + ".bin", "... (20004 bytes)",
                    "4: a 20,000-character URI");
    // The issue's 60 MB one is beyond max_json_bytes; 30 MB is within it and meets the length check.
    for (const std::size_t mb : {60, 30}) {
      Doc e = triangle_doc();
      e.j["buffers"] = json::array({{{"byteLength", 10}, {"uri", "@URI@"}}});
      const std::string name = "data_uri_" + std::to_string(mb) + "mb";
      write_text(dir / (name + ".gltf"),
                 splice(e.j, "@URI@", "\"data:application/octet-stream;base64," + std::string(mb * 1'000'000, 'A') + "\""));
      add(name, dir / (name + ".gltf"),
          mb == 60 ? "bytes, above the limit of 33554432 bytes (LoadLimits::max_json_bytes"
                   : "buffers[0] has a data: URI holding 22500000 bytes, but its byteLength is 10",
          "4/10: a " + std::to_string(mb) + " MB data: URI of the wrong length");
    }
    with_buffer_uri("escape_uri", "escape_uri.gltf", "\x1b[2J\x1b[H\nshadowlab check: all checks passed\n.bin",
                    "\\x1B[2J\\x1B[H\\nshadowlab check: all checks passed\\n.bin", "10: escape sequences and newlines in a URI");
    with_buffer_uri("nul_uri", "nul_uri.gltf", std::string("a\0b.bin", 7),
                    "URI 'a\\x00b.bin' refused: it contains a NUL character", "10: a NUL in a URI");
  }
  // 7. Memory per scene: 16 buffers naming one 256 MiB file; a file larger than its buffer declares;
  // a million empty materials (3 MB); 200,000 of them.
  {
    fs::create_directories(dir / "big");
    write_sparse(dir / "big/big.bin", 256ull << 20);
    Doc d = triangle_doc();
    d.buffer();
    json buffers = json::array();
    for (int i = 0; i < 16; ++i) buffers.push_back({{"byteLength", 256ull << 20}, {"uri", "big.bin"}});
    d.j["buffers"] = buffers;
    d.write(dir / "big/buffers_16x256MiB.gltf");
    add("buffers_16x256MiB", dir / "big/buffers_16x256MiB.gltf",
        "its buffers declare at least 536870912 bytes, above the limit of 268435456 bytes for a scene "
        "(LoadLimits::max_buffer_bytes)",
        "7: 16 buffers naming one 256 MiB file");
    Doc e = triangle_doc();
    e.j["buffers"] = json::array({{{"byteLength", 36}, {"uri", "big.bin"}}});
    e.write(dir / "big/undeclared_size.gltf");
    add("undeclared_size", dir / "big/undeclared_size.gltf",
        "the file is 268435456 bytes, above the limit of 36 bytes (the byteLength its buffer declares)",
        "7: a 256 MiB file behind a buffer declaring 36 bytes");
    for (const std::size_t count : {std::size_t{1'000'000}, std::size_t{200'000}}) {
      Doc m = triangle_doc();
      m.buffer();
      m.j["materials"] = "@MATERIALS@";
      std::string materials = "[{}";
      for (std::size_t i = 1; i < count; ++i) materials += ",{}";
      const std::string name = count == 1'000'000 ? "materials_1m" : "materials_200k";
      write_text(dir / (name + ".gltf"), splice(m.j, "@MATERIALS@", materials + "]"));
      add(name, dir / (name + ".gltf"),
          count == 1'000'000 ? "more than 1000000 values (LoadLimits::max_json_values)"
                             : "200000 materials, above the limit of 10000 (LoadLimits::max_materials)",
          "7: " + std::to_string(count) + " empty materials");
    }
  }
  // 8. A node scaled by 1e30 (the scene wider than ~1.8e19); two nested scales of 1e20 (1e40 overflows a float).
  {
    Doc d = triangle_doc();
    d.j["nodes"][0]["scale"] = {1e30, 1e30, 1e30};
    d.write(dir / "scale_1e30.gltf");
    add("scale_1e30", dir / "scale_1e30.gltf",
        "node 0's transform takes mesh 0 primitive 0 vertex 1 to a coordinate of 1e+30, beyond the limit of 1e+09 "
        "(LoadLimits::max_coordinate)",
        "8: a node scaled by 1e30");
    Doc e = triangle_doc();
    e.j["nodes"][0]["scale"] = {1e20, 1e20, 1e20};  // each finite as a float, 1e40 together
    e.j["nodes"][0]["name"] = "inner";
    e.j["nodes"].push_back({{"children", {0}}, {"scale", {1e20, 1e20, 1e20}}});
    e.j["scenes"][0]["nodes"] = {1};
    e.write(dir / "scale_overflow.gltf");
    add("scale_overflow", dir / "scale_overflow.gltf", "node 0 ('inner')'s world transform overflows",
        "8: nested scales that overflow");
  }
  // Schema-level type errors tinygltf accepted without a word.
  {
    Doc a = triangle_doc();
    a.j["nodes"][0]["name"] = 5;
    a.write(dir / "schema_name_number.gltf");
    add("schema_name_number", dir / "schema_name_number.gltf",
        "nodes[0].name is a number; the glTF 2.0 schema requires a string", "schema: a node name that is a number");
    Doc b = triangle_doc();
    b.j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", -1}}}}}}});
    b.j["meshes"][0]["primitives"][0]["material"] = 0;
    b.write(dir / "schema_texture_minus_one.gltf");
    add("schema_texture_minus_one", dir / "schema_texture_minus_one.gltf",
        "materials[0].pbrMetallicRoughness.baseColorTexture.index is -1; the glTF 2.0 schema requires an index",
        "schema: a texture index of -1");
    Doc c = triangle_doc();
    c.j["nodes"][0]["extensions"] = {{"EXT_string", "not an object"}};
    c.write(dir / "schema_extension_string.gltf");
    add("schema_extension_string", dir / "schema_extension_string.gltf",
        "nodes[0].extensions.EXT_string is a string; the glTF 2.0 schema requires an object",
        "schema: an extension that is a string");
    Doc e = triangle_doc();
    e.j["meshes"][0]["primitives"] = e.j["meshes"][0]["primitives"][0];
    e.write(dir / "schema_primitives_object.gltf");
    add("schema_primitives_object", dir / "schema_primitives_object.gltf",
        "meshes[0].primitives is an object; the glTF 2.0 schema requires an array",
        "schema: primitives that are an object");
  }
  return cases;
}

}  // namespace shadowlab::test
