#include "scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>

namespace shadowlab {

Bounds Mesh::bounds() const {
  Bounds b;
  for (const auto& p : positions) b.extend(p);
  return b;
}

Bounds Scene::bounds() const {
  Bounds b;
  for (const auto& m : meshes) b.extend(m.bounds());
  return b;
}

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.triangle_count();
  return n;
}

namespace {

// A texel coordinate under a glTF wrap mode (33071 clamp, 33648 mirrored repeat, else repeat).
int wrap_texel(int i, int n, int mode) {
  if (mode == 33071) return std::clamp(i, 0, n - 1);
  if (mode == 33648) {
    const int period = 2 * n;
    int m = ((i % period) + period) % period;
    return m < n ? m : period - 1 - m;
  }
  return ((i % n) + n) % n;
}

glm::vec4 texel(const Texture& t, int x, int y) {
  x = wrap_texel(x, t.width, t.wrap_s);
  y = wrap_texel(y, t.height, t.wrap_t);
  const std::uint8_t* p = t.rgba->data() + 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(t.width) + x);
  return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

}  // namespace

glm::vec4 sample_texture(const Texture& t, glm::vec2 uv) {
  if (!t.rgba || t.width <= 0 || t.height <= 0) return glm::vec4(1.0f);
  // Rows are stored top row first and uploaded as given, so v = 0 is the first row (glTF's convention).
  const float x = uv.x * static_cast<float>(t.width), y = uv.y * static_cast<float>(t.height);
  if (t.mag_filter == 9728) return texel(t, static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  const float fx = x - 0.5f, fy = y - 0.5f;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const float ax = fx - static_cast<float>(x0), ay = fy - static_cast<float>(y0);
  const glm::vec4 top = glm::mix(texel(t, x0, y0), texel(t, x0 + 1, y0), ax);
  const glm::vec4 bottom = glm::mix(texel(t, x0, y0 + 1), texel(t, x0 + 1, y0 + 1), ax);
  return glm::mix(top, bottom, ay);
}

float Mesh::alpha_at(const std::vector<Texture>& textures, std::size_t t, float u, float v) const {
  const std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
  const float w = 1.0f - u - v;
  float alpha = this->alpha;
  if (!colors.empty()) alpha *= w * colors[a].a + u * colors[b].a + v * colors[c].a;
  if (texture >= 0 && static_cast<std::size_t>(texture) < textures.size() && !uvs.empty())
    alpha *= sample_texture(textures[static_cast<std::size_t>(texture)], w * uvs[a] + u * uvs[b] + v * uvs[c]).a;
  if (shape_alpha && !uvs.empty()) alpha *= shape_alpha(w * uvs[a] + u * uvs[b] + v * uvs[c]);
  return alpha;
}

bool has_ground(const Scene& scene) {
  const Bounds box = scene.bounds();
  if (box.empty()) return true;  // nothing to stand on anything
  const glm::vec3 size = box.extent();
  const float footprint = size.x * size.z;
  if (!(footprint > 0.0f)) return false;
  const float top = box.min.y + 0.25f * size.y;
  double area = 0.0;
  for (const Mesh& m : scene.meshes)
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const glm::vec3 &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
                      &c = m.positions[m.indices[3 * t + 2]];
      if (std::max({a.y, b.y, c.y}) > top) continue;
      const glm::vec3 n = glm::cross(b - a, c - a);
      const float len = glm::length(n);
      // Facing up (counter-clockwise seen from above): a model's own flat underside faces down.
      if (len > 0.0f && n.y > 0.9f * len) area += 0.5 * len;
    }
  return area >= 0.25 * footprint;
}

Scene with_ground(const Scene& scene, bool add) {
  if (!add) return scene;
  Scene out = scene;
  const Bounds box = scene.bounds();
  if (box.empty()) return out;
  const float half = 2.0f * std::max({box.extent().x, box.extent().z, 0.5f * box.extent().y, 1e-3f});
  Mesh ground = make_plane({box.center().x, box.min.y, box.center().z}, half, half, {0.75f, 0.75f, 0.72f});
  ground.name = "ground";
  ground.ground = true;
  out.meshes.push_back(std::move(ground));
  return out;
}

void compute_normals(Mesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    // The cross product's length is twice the area, so larger faces weigh more.
    const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    mesh.normals[a] += n;
    mesh.normals[b] += n;
    mesh.normals[c] += n;
  }
  for (auto& n : mesh.normals) {
    const float len = glm::length(n);
    n = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

void transform_mesh(Mesh& mesh, const glm::mat4& transform) {
  const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(transform));
  for (auto& p : mesh.positions) p = glm::vec3(transform * glm::vec4(p, 1.0f));
  for (auto& n : mesh.normals) {
    const glm::vec3 t = normal_matrix * n;
    const float len = glm::length(t);
    n = len > 0.0f && std::isfinite(len) ? t / len : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  // A mirroring transform flips the winding; swap two indices so front faces stay front faces.
  if (glm::determinant(glm::mat3(transform)) < 0.0f) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  }
}

Mesh make_box(const glm::vec3& center, const glm::vec3& half_size, const glm::vec3& color) {
  Mesh m;
  m.name = "box";
  m.color = color;
  // Six faces with their own vertices, so normals stay flat. Each face: normal n, in-plane axes u, v
  // with u x v = n, so the quad (-u-v, +u-v, +u+v, -u+v) winds counter-clockwise seen from outside.
  const glm::vec3 axes[6][3] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
  };
  for (const auto& face : axes) {
    const glm::vec3 n = face[0], u = face[1], v = face[2];
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
      m.positions.push_back(center + half_size * (n + su[k] * u + sv[k] * v));
      m.normals.push_back(n);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
  }
  return m;
}

Mesh make_plane(const glm::vec3& center, float half_size_x, float half_size_z, const glm::vec3& color) {
  Mesh m;
  m.name = "plane";
  m.color = color;
  m.positions = {center + glm::vec3(-half_size_x, 0, half_size_z), center + glm::vec3(half_size_x, 0, half_size_z),
                 center + glm::vec3(half_size_x, 0, -half_size_z), center + glm::vec3(-half_size_x, 0, -half_size_z)};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

Mesh make_sphere(const glm::vec3& center, float radius, int slices, int stacks, const glm::vec3& color) {
  Mesh m;
  m.name = "sphere";
  m.color = color;
  const float pi = std::numbers::pi_v<float>;
  for (int i = 0; i <= stacks; ++i) {
    const float theta = pi * static_cast<float>(i) / static_cast<float>(stacks);
    // sin(pi) is -8.7e-8 in float: make both poles exact points, so the mesh closes (shadow volumes
    // need every edge shared).
    const float ring = (i == 0 || i == stacks) ? 0.0f : std::sin(theta);
    const float height = i == 0 ? 1.0f : i == stacks ? -1.0f : std::cos(theta);
    for (int j = 0; j <= slices; ++j) {
      // The last column repeats the first exactly (sin(2 pi) is not 0 in float either): a closed seam.
      const float phi = j == slices ? 0.0f : 2.0f * pi * static_cast<float>(j) / static_cast<float>(slices);
      const glm::vec3 n(ring * std::cos(phi), height, -ring * std::sin(phi));
      m.positions.push_back(center + radius * n);
      m.normals.push_back(n);
    }
  }
  const auto row = static_cast<std::uint32_t>(slices + 1);
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const std::uint32_t a = static_cast<std::uint32_t>(i) * row + static_cast<std::uint32_t>(j);
      const std::uint32_t b = a + row;
      if (i != 0) m.indices.insert(m.indices.end(), {a, b, a + 1});
      if (i != stacks - 1) m.indices.insert(m.indices.end(), {a + 1, b, b + 1});
    }
  }
  return m;
}

namespace {
void add_named(Scene& scene, Mesh mesh, const char* name) {
  mesh.name = name;
  scene.meshes.push_back(std::move(mesh));
}
}  // namespace

Scene make_default_scene() {
  Scene s;
  s.name = "default";
  add_named(s, make_plane({0, 0, 0}, 6.0f, 6.0f, {0.75f, 0.75f, 0.72f}), "ground");
  add_named(s, make_box({-2.5f, 1.0f, -1.5f}, {1.0f, 1.0f, 1.0f}, {0.80f, 0.35f, 0.30f}), "box");
  add_named(s, make_box({2.0f, 0.6f, 2.2f}, {0.6f, 0.6f, 0.6f}, {0.30f, 0.55f, 0.80f}), "small box");
  add_named(s, make_sphere({1.8f, 1.2f, -1.8f}, 1.2f, 48, 24, {0.35f, 0.75f, 0.40f}), "sphere");
  // Thin slab 0.8 above the ground: with too large a bias its shadow lifts off ("peter-panning").
  add_named(s, make_box({-1.8f, 0.9f, 2.4f}, {1.3f, 0.06f, 0.9f}, {0.85f, 0.70f, 0.30f}), "floating slab");
  // Thin vertical plate standing on the ground: grazing light gives acne on it and leaks under it.
  add_named(s, make_box({0.2f, 1.1f, 0.3f}, {0.04f, 1.1f, 1.2f}, {0.70f, 0.50f, 0.80f}), "thin plate");
  return s;
}

Scene make_stacked_occluders_scene() {
  Scene s;
  s.name = "stacked";
  add_named(s, make_plane({0, 0, 0}, 6.0f, 6.0f, {0.75f, 0.75f, 0.72f}), "receiver");
  // Each occluder overlaps the one below it only in part, so the receiver sees regions shadowed by one,
  // two or three layers: where a higher occluder covers a lower one, VSM's bound leaks light.
  add_named(s, make_box({-0.8f, 0.6f, 0.0f}, {1.2f, 0.05f, 1.2f}, {0.8f, 0.3f, 0.3f}), "low occluder");
  add_named(s, make_box({0.4f, 1.8f, 0.3f}, {1.2f, 0.05f, 1.2f}, {0.3f, 0.7f, 0.3f}), "middle occluder");
  add_named(s, make_box({0.0f, 3.4f, -0.6f}, {1.0f, 0.05f, 1.0f}, {0.3f, 0.4f, 0.8f}), "high occluder");
  return s;
}

Scene builtin_scene(std::string_view name) {
  if (name.empty() || name == "default") return make_default_scene();
  if (name == "stacked") return make_stacked_occluders_scene();
  throw std::invalid_argument("no built-in scene '" + std::string(name) + "'; the built-in scenes: 'default', 'stacked'");
}

}  // namespace shadowlab
