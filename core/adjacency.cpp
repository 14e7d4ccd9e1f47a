#include "core/adjacency.h"

#include <cstring>
#include <unordered_map>

namespace shadowlab {

namespace {

struct PositionHash {
  std::size_t operator()(const glm::vec3& p) const {
    std::uint32_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    return (static_cast<std::size_t>(bits[0]) * 73856093u) ^ (static_cast<std::size_t>(bits[1]) * 19349663u) ^
           (static_cast<std::size_t>(bits[2]) * 83492791u);
  }
};

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (static_cast<std::uint64_t>(a) << 32) | b : (static_cast<std::uint64_t>(b) << 32) | a;
}

struct EdgeUse {
  std::uint32_t triangle;
  std::uint32_t from, to;  // welded ids, in the triangle's winding order
  std::uint32_t opposite;  // the triangle's vertex (original index) not on this edge
};

}  // namespace

Adjacency build_adjacency(const Mesh& mesh) {
  // 1. Weld: positions that are bit-identical share one id (-0.0 and 0.0 are folded first).
  std::unordered_map<glm::vec3, std::uint32_t, PositionHash> ids;
  std::vector<std::uint32_t> welded(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i] + glm::vec3(0.0f);
    welded[i] = ids.emplace(p, static_cast<std::uint32_t>(ids.size())).first->second;
  }
  // 2. Every edge with the triangles that use it.
  std::unordered_map<std::uint64_t, std::vector<EdgeUse>> edges;
  const std::size_t triangles = mesh.indices.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t* v = &mesh.indices[3 * t];
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = welded[v[e]], b = welded[v[(e + 1) % 3]];
      edges[edge_key(a, b)].push_back({static_cast<std::uint32_t>(t), a, b, v[(e + 2) % 3]});
    }
  }
  Adjacency adj;
  adj.edges = edges.size();
  for (const auto& [key, uses] : edges) {
    if (uses.size() == 1) ++adj.open_edges;
    if (uses.size() > 2) ++adj.non_manifold_edges;
    if (uses.size() == 2 && uses[0].from == uses[1].from) ++adj.inconsistent_edges;
  }
  // 3. Six indices per triangle: for each edge, the neighbour traversing it the other way (a manifold
  // neighbour); failing that any other user; failing that (an open edge) the triangle's own opposite.
  adj.indices.resize(6 * triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t* v = &mesh.indices[3 * t];
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = welded[v[e]], b = welded[v[(e + 1) % 3]];
      const auto& uses = edges[edge_key(a, b)];
      std::uint32_t neighbour = v[(e + 2) % 3];
      bool found = false;
      for (const auto& u : uses) {
        if (u.triangle == t) continue;
        if (u.from == b && u.to == a) {
          neighbour = u.opposite;
          found = true;
          break;
        }
      }
      for (const auto& u : uses) {
        if (found) break;
        if (u.triangle != t) {
          neighbour = u.opposite;
          found = true;
        }
      }
      adj.indices[6 * t + 2 * static_cast<std::size_t>(e)] = v[e];
      adj.indices[6 * t + 2 * static_cast<std::size_t>(e) + 1] = neighbour;
    }
  }
  return adj;
}

}  // namespace shadowlab
