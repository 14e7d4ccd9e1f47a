// glTF 2.0 loading. tinygltf parses the JSON/GLB and the buffers; everything it hands back is checked
// here before use, because tinygltf 2.7.0 accepts out-of-range indices, accessors running past their
// buffers, node loops and the like without a word.
//
// The order of the checks matters:
//   1. the file itself (a regular file, its size limit before reading, GLB version and chunks); its
//      JSON measured (depth, values, array sizes) and type-checked against the glTF 2.0 schema, the
//      buffers' declared sizes summed against the scene's budget; then tinygltf, whose file reads go
//      through a sandbox that opens files only inside the model's folder, relative to its handle;
//   2. every index reference in the document, buffer views against their buffers, accessor layouts;
//   3. the node hierarchy (one parent per node, no loops, depth limit, finite transforms);
//   4. the scene walk, which lists the triangle primitives to draw and checks their formats, the
//      instances and the declared vertex/triangle totals against LoadLimits, before anything is
//      allocated for them;
//   5. accessor byte ranges against their buffer views (after 4, so that a file declaring billions of
//      vertices is refused for the limit it breaks, whatever else is wrong with it);
//   6. reading: positions must be finite, indices in range, world positions within max_coordinate;
//      normals are used when they are sound.
//
// The steps live in files of their own, the Loader class they share in core/gltf_loader_parts.h:
// core/gltf_file.cpp (1), core/gltf_references.cpp (2, 3), core/gltf_scene_walk.cpp (4, 5),
// core/gltf_meshes.cpp (6) and core/gltf_materials.cpp (images, textures, materials).
#include "core/gltf_loader.h"

#include "core/gltf_loader_parts.h"

namespace shadowlab {
namespace gltf_detail {

Scene Loader::load() {
  parse();
  check_asset();
  check_references();
  name_accessor_roles();
  check_buffer_views();
  check_accessor_layouts();
  check_nodes();
  const std::vector<Draw> draws = walk_scene();
  check_accessor_ranges();

  Scene scene;
  scene.name = printable(path_.string(), 400);
  scene.textures = build_textures();
  scene.meshes.reserve(draws.size());
  for (const Draw& d : draws) scene.meshes.push_back(build_mesh(d));
  if (scene.meshes.empty()) fail("no triangle meshes to draw");
  // World positions in double; the float vertices relative to the scene's origin (core/placement.h).
  scene.origin = far_origin(scene.meshes, draws);
  for (std::size_t i = 0; i < draws.size(); ++i) place_mesh(scene.meshes[i], draws[i], scene.origin);
  return scene;
}

}  // namespace gltf_detail

Scene load_gltf(const std::filesystem::path& path, const LoadLimits& limits, std::vector<std::string>* warnings) {
  gltf_detail::Loader loader(path, limits);
  Scene scene = loader.load();
  if (warnings) *warnings = loader.warnings();
  return scene;
}

}  // namespace shadowlab
