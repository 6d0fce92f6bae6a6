#pragma once
// Closed triangulated membrane surface (Sec. 2.5): an icosahedron refined by edge
// bisection, its topology (edges, ordered one-rings) and the orientation convention.
//
// Convention (fixed once for the whole 3D membrane): every triangle (i, j, k) is
// counter-clockwise seen from outside, so (x_j - x_i) x (x_k - x_i) points along the
// OUTWARD normal.
#include <Eigen/Dense>
#include <array>
#include <vector>

namespace capsule::membrane3d {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

struct Mesh {
  std::vector<Vec3> x;                 // vertex positions
  std::vector<Triangle> triangles;     // outward-oriented vertex triples
  std::vector<std::array<int, 2>> edges;            // each undirected edge once (i < j)
  std::vector<std::vector<int>> ring;               // one-ring neighbours, counter-clockwise about the outward normal
  std::vector<std::vector<int>> vertex_triangles;   // triangles incident to each vertex
  std::vector<std::vector<int>> corner_in_triangle; // local index (0..2) of the vertex in vertex_triangles[v][n]

  int vertex_count() const { return static_cast<int>(x.size()); }
  int triangle_count() const { return static_cast<int>(triangles.size()); }
};

// Unit sphere: icosahedron (level 0: 12 vertices, 20 triangles) refined `level` times by
// bisecting every edge and splitting each face into four; new vertices projected to the
// unit sphere. V = 10 4^level + 2, E = 30 4^level, F = 20 4^level.
Mesh unit_icosphere(int level);

// Fills edges, rings and incidence lists from `triangles`. Throws std::runtime_error if
// the surface is not a closed, consistently oriented 2-manifold.
void build_topology(Mesh& mesh);

}  // namespace capsule::membrane3d
