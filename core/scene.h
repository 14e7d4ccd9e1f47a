// Scene: triangle meshes in world space, the input of every pass and of the ray-cast oracle.
//
// Node transforms are baked into the vertices when a scene is built or loaded: the lab's scenes are
// static, and one world-space copy keeps the shadow passes, the lit pass and the oracle looking at
// exactly the same triangles.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Bounds& b) {
    if (!b.empty()) {
      extend(b.min);
      extend(b.max);
    }
  }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
  // The eight corners, in the order (x, y, z) bits of the index: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
  glm::vec3 corner(int i) const {
    return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
  }
};

// A decoded base-colour image with its sampler (glTF's enums: GL_REPEAT 10497, GL_CLAMP_TO_EDGE 33071,
// GL_MIRRORED_REPEAT 33648, GL_NEAREST 9728, GL_LINEAR 9729, the mipmap filters 9984-9987). An image
// that could not be decoded is a checker (problem says why), so a bad file shows and never crashes.
struct Texture {
  std::string name;     // for messages: the image's URI or "image N"
  int width = 0, height = 0;
  std::shared_ptr<const std::vector<std::uint8_t>> rgba;  // width * height * 4, top row first (glTF's order)
  int wrap_s = 10497, wrap_t = 10497;
  int min_filter = 9987, mag_filter = 9729;
  std::string problem;  // empty when the image decoded
};

// The texture at uv as the GPU's magnification filter reads its first level (nearest or bilinear, with the
// sampler's wrap), in [0, 1] per channel: the oracle's alpha test.
glm::vec4 sample_texture(const Texture& texture, glm::vec2 uv);

enum class AlphaMode { Opaque, Mask, Blend };

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // world space
  std::vector<glm::vec3> normals;    // world space, unit length, one per position
  std::vector<std::uint32_t> indices;  // triangle list; every index < positions.size()
  glm::vec3 color{0.8f};  // the base colour factor's rgb
  bool casts_shadow = true;
  // Materials as far as shadows need them (glTF): the factor's alpha, vertex colours (COLOR_0, empty
  // when none: white), TEXCOORD_0 (empty when none) and the base-colour texture (index into
  // Scene::textures, -1: none), and the alpha mode with its cutoff.
  float alpha = 1.0f;
  std::vector<glm::vec4> colors;
  std::vector<glm::vec2> uvs;
  int texture = -1;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  // An analytic cut-out multiplied into the alpha at the point's uv (null: none): lab 11's billboards,
  // whose shaders compute the same function (renderer/billboards.h).
  float (*shape_alpha)(glm::vec2 uv) = nullptr;
  bool ground = false;  // the ground plane added by with_ground()

  // The alpha the material gives a point of triangle t at barycentrics (u, v) (factor x vertex colour x
  // texture x shape_alpha), as the lit and shadow passes compute it; `textures` is the scene's.
  float alpha_at(const std::vector<Texture>& textures, std::size_t t, float u, float v) const;
  // True when this point is cut out (MASK below the cutoff).
  bool cut_out(const std::vector<Texture>& textures, std::size_t t, float u, float v) const {
    return alpha_mode == AlphaMode::Mask && alpha_at(textures, t, u, v) < alpha_cutoff;
  }

  std::size_t triangle_count() const { return indices.size() / 3; }
  Bounds bounds() const;
};

struct Scene {
  std::string name;  // "default" for the built-in scene, else the file it came from
  std::vector<Mesh> meshes;
  std::vector<Texture> textures;  // decoded once per image of the file
  // Where the vertices' origin stands in the world, in double: a model far from the world's origin keeps
  // float offsets from the centre of its box here (the glTF loader decides), so its shape survives. The
  // vertices, the bounds and everything graded are in the scene's own frame (relative to this point);
  // the renderer places the scene at origin + p (core/placement.h).
  glm::dvec3 origin{0.0};

  Bounds bounds() const;
  std::size_t triangle_count() const;
};

// Whether a scene has its own receiver: an upward-facing roughly horizontal (n.y > 0.9) surface in the bottom quarter of
// the box's height covering at least a quarter of the box's footprint (x by z). Without one a dropped
// model's shadow falls on nothing.
bool has_ground(const Scene& scene);
// The scene with a ground plane (mesh named "ground", Mesh::ground set) at the bottom of its box, four times
// the box's larger horizontal extent on a side, centred under it. `add` false returns the scene as is.
Scene with_ground(const Scene& scene, bool add);

// Fills in smooth per-vertex normals (area-weighted face normals) for a mesh that has none.
void compute_normals(Mesh& mesh);

// Applies a transform to positions and normals (normals by the inverse transpose, renormalised).
void transform_mesh(Mesh& mesh, const glm::mat4& transform);

// The built-in scene, made in code so the lab runs with no files: a ground plane, two boxes, a sphere,
// a slab floating above the ground and a thin vertical plate. The slab shows peter-panning (its shadow
// detaches when the bias grows) and the plate shows acne and light leaking through thin geometry.
Scene make_default_scene();

// Occluders stacked at different heights over a receiver: the textbook case of VSM light bleeding.
Scene make_stacked_occluders_scene();

// A built-in scene by its name (Scene::name): "default" (or empty) or "stacked", as a preset names it;
// throws std::invalid_argument listing the names otherwise.
Scene builtin_scene(std::string_view name);

// Shapes used by the built-in scenes and by tests.
Mesh make_box(const glm::vec3& center, const glm::vec3& half_size, const glm::vec3& color);
Mesh make_plane(const glm::vec3& center, float half_size_x, float half_size_z, const glm::vec3& color);
Mesh make_sphere(const glm::vec3& center, float radius, int slices, int stacks, const glm::vec3& color);

}  // namespace shadowlab
