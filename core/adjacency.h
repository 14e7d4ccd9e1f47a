// Triangle adjacency for stencil shadow volumes: each triangle (a, b, c) becomes the six indices
// a, n_ab, b, n_bc, c, n_ca of GL_TRIANGLES_ADJACENCY, where n_xy is the vertex opposite edge xy in the
// neighbouring triangle. Vertices are welded by position first: a box has split vertices per face for
// flat normals, but its edges are still shared.
//
// Shadow volumes need closed, manifold meshes. Open edges (one triangle) and non-manifold edges (three
// or more) are counted and reported, not hidden: an open edge gets the triangle's own opposite vertex as
// its neighbour, so it is always treated as a silhouette (the volume stays closed on that side).
#pragma once

#include <cstdint>
#include <vector>

#include "core/scene.h"

namespace shadowlab {

struct Adjacency {
  std::vector<std::uint32_t> indices;  // 6 per triangle, into the mesh's own vertex array
  std::size_t edges = 0;
  std::size_t open_edges = 0;         // used by one triangle only
  std::size_t non_manifold_edges = 0; // used by three or more
  std::size_t inconsistent_edges = 0; // two triangles traversing the edge the same way (flipped winding)

  bool closed_manifold() const { return open_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0; }
};

Adjacency build_adjacency(const Mesh& mesh);

}  // namespace shadowlab
