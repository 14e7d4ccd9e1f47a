#include "renderer/gpu_mesh.h"

#include <cstddef>

#include "core/light.h"

namespace shadowlab {

namespace {
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec4 color;  // base colour factor x COLOR_0, alpha included
  glm::vec2 uv;     // TEXCOORD_0 of the base-colour texture
};
// A scene without materials keeps the layout it had before them (36 bytes, three attributes): on
// llvmpipe the wider vertex made lab 6's frame 30 % dearer.
struct PlainVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
};

GLint gl_filter(int gltf, bool minification) {
  switch (gltf) {
    case 9728: return GL_NEAREST;
    case 9729: return GL_LINEAR;
    case 9984: return GL_NEAREST_MIPMAP_NEAREST;
    case 9985: return GL_LINEAR_MIPMAP_NEAREST;
    case 9986: return GL_NEAREST_MIPMAP_LINEAR;
    case 9987: return GL_LINEAR_MIPMAP_LINEAR;
    default: return minification ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR;
  }
}

GLint gl_wrap(int gltf) { return gltf == 33071 ? GL_CLAMP_TO_EDGE : gltf == 33648 ? GL_MIRRORED_REPEAT : GL_REPEAT; }

GlTexture upload(const Texture& t) {
  GlTexture tex = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, tex.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, t.width, t.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba->data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(t.wrap_s));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(t.wrap_t));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, gl_filter(t.min_filter, true));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, gl_filter(t.mag_filter, false) == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
  glGenerateMipmap(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  return tex;
}

}  // namespace

GpuScene::GpuScene(const Scene& scene)
    : vao_(GlVertexArray::create()), vertices_(GlBuffer::create()), indices_(GlBuffer::create()) {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  for (const Mesh& mesh : scene.meshes) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    Range range;
    range.first_index = static_cast<std::uint32_t>(indices.size());
    range.index_count = static_cast<std::uint32_t>(mesh.indices.size());
    range.bounds = mesh.bounds();
    bounds_.extend(range.bounds);
    range.casts_shadow = mesh.casts_shadow;
    const bool textured = mesh.texture >= 0 && static_cast<std::size_t>(mesh.texture) < scene.textures.size() &&
                          mesh.uvs.size() == mesh.positions.size();
    range.texture = textured ? mesh.texture : -1;
    range.alpha_mode = mesh.alpha_mode;
    range.alpha_cutoff = mesh.alpha_cutoff;
    has_materials_ = has_materials_ || textured || mesh.alpha_mode != AlphaMode::Opaque;
    has_masked_casters_ = has_masked_casters_ || (mesh.alpha_mode == AlphaMode::Mask && mesh.casts_shadow);
    const glm::vec4 factor(mesh.color, mesh.alpha);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      vertices.push_back({mesh.positions[i], i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0),
                          i < mesh.colors.size() ? factor * mesh.colors[i] : factor,
                          textured ? mesh.uvs[i] : glm::vec2(0.0f)});
    for (std::uint32_t index : mesh.indices) indices.push_back(base + index);
    ranges_.push_back(range);
    triangles_ += mesh.triangle_count();
  }
  if (has_materials_) {
    for (const Texture& t : scene.textures) textures_.push_back(upload(t));
    Texture white;
    white.width = white.height = 1;
    white.rgba = std::make_shared<const std::vector<std::uint8_t>>(4, std::uint8_t{255});
    white.min_filter = white.mag_filter = 9728;
    white_ = upload(white);
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  if (has_materials_) {
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
  } else {
    std::vector<PlainVertex> plain(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
      plain[i] = {vertices[i].position, vertices[i].normal, glm::vec3(vertices[i].color)};
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(plain.size() * sizeof(PlainVertex)), plain.data(), GL_STATIC_DRAW);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  // Attribute locations are fixed across all shaders: 0 position, 1 normal, 2 colour (RGB; with
  // materials RGBA, and 3 the texture coordinates).
  const auto stride = static_cast<GLsizei>(has_materials_ ? sizeof(Vertex) : sizeof(PlainVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, has_materials_ ? 4 : 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, color)));
  if (has_materials_) {
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, uv)));
  }
  glBindVertexArray(0);
}

void GpuScene::draw(const Range& range) const {
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(range.index_count), GL_UNSIGNED_INT,
                 reinterpret_cast<void*>(static_cast<std::uintptr_t>(range.first_index) * sizeof(std::uint32_t)));
}

void GpuScene::bind_texture(const Range& range, int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, range.texture >= 0 ? textures_[static_cast<std::size_t>(range.texture)].id() : white_.id());
  glActiveTexture(GL_TEXTURE0);
}

GpuScene::CasterCounts GpuScene::draw_casters(const glm::mat4* light_view_projs, int count, bool cull,
                                              const std::function<void(const Range&)>* masked) const {
  bind();
  CasterCounts counts;
  const bool split = masked && has_masked_casters_;
  for (int round = 0; round < (split ? 2 : 1); ++round)
  for (const auto& range : ranges_) {
    if (!range.casts_shadow) continue;
    if (split && (range.alpha_mode == AlphaMode::Mask) != (round == 1)) continue;
    bool inside = !cull;
    for (int i = 0; i < count && !inside; ++i) inside = !box_outside_clip_volume(range.bounds, light_view_projs[i]);
    if (!inside) {
      ++counts.culled;
      continue;
    }
    if (round == 1) (*masked)(range);
    draw(range);
    ++counts.drawn;
  }
  return counts;
}

}  // namespace shadowlab
