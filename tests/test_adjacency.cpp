// Adjacency for shadow volumes: neighbours across every edge of closed meshes, open and non-manifold
// edges counted.
#include <gtest/gtest.h>

#include "core/adjacency.h"

namespace shadowlab {
namespace {

// For each triangle's edge (a, b) the neighbour vertex n must belong to a triangle that contains the
// edge's two positions and n; for a closed mesh that triangle is a different one.
void expect_neighbours_share_edges(const Mesh& m, const Adjacency& adj) {
  ASSERT_EQ(adj.indices.size(), m.indices.size() * 2);
  for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
    for (int e = 0; e < 3; ++e) {
      const glm::vec3 a = m.positions[adj.indices[6 * t + 2 * e]];
      const glm::vec3 b = m.positions[adj.indices[6 * t + (2 * e + 2) % 6]];
      const glm::vec3 n = m.positions[adj.indices[6 * t + 2 * e + 1]];
      bool found = false;
      for (std::size_t u = 0; u < m.indices.size() / 3 && !found; ++u) {
        if (u == t) continue;
        int hits = 0;
        bool has_n = false;
        for (int k = 0; k < 3; ++k) {
          const glm::vec3 p = m.positions[m.indices[3 * u + k]];
          hits += (p == a) + (p == b);
          has_n = has_n || p == n;
        }
        found = hits == 2 && has_n;
      }
      EXPECT_TRUE(found) << "triangle " << t << " edge " << e;
    }
  }
}

TEST(Adjacency, BoxIsClosedAfterWelding) {
  const Mesh box = make_box({0, 0, 0}, {1, 2, 3}, glm::vec3(1));
  const Adjacency adj = build_adjacency(box);
  EXPECT_EQ(adj.edges, 18u);  // 12 cube edges + 6 face diagonals
  EXPECT_TRUE(adj.closed_manifold());
  expect_neighbours_share_edges(box, adj);
}

TEST(Adjacency, SphereIsClosed) {
  const Mesh sphere = make_sphere({0, 0, 0}, 1.0f, 16, 8, glm::vec3(1));
  const Adjacency adj = build_adjacency(sphere);
  EXPECT_EQ(adj.open_edges, 0u);
  EXPECT_EQ(adj.non_manifold_edges, 0u);
}

TEST(Adjacency, PlaneHasOpenEdgesTreatedAsSilhouettes) {
  const Mesh plane = make_plane({0, 0, 0}, 1, 1, glm::vec3(1));
  const Adjacency adj = build_adjacency(plane);
  EXPECT_EQ(adj.edges, 5u);
  EXPECT_EQ(adj.open_edges, 4u);
  EXPECT_FALSE(adj.closed_manifold());
  // Open edge: the neighbour is the triangle's own opposite vertex.
  const std::uint32_t* v = &plane.indices[0];
  EXPECT_EQ(adj.indices[1], v[2]);  // edge (v0, v1) of triangle 0 lies on the border
}

TEST(Adjacency, NonManifoldAndFlippedEdgesAreCounted) {
  Mesh fin;
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};  // three triangles on edge (0, 1)
  EXPECT_EQ(build_adjacency(fin).non_manifold_edges, 1u);
  Mesh flipped;
  flipped.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  flipped.indices = {0, 1, 2, 0, 1, 3};  // both traverse 0 -> 1
  EXPECT_EQ(build_adjacency(flipped).inconsistent_edges, 1u);
}

}  // namespace
}  // namespace shadowlab
