#pragma once
// Central slices of a 3D capsule, as drawn in Figs. 41-53 (Sec. 4.2): the capsule is rotated
// about the z axis through its volume centroid by -theta (theta: inclination of the inertia
// ellipse's major axis, inertia_deformation), so that it sits at theta = 0, and is cut by the
// plane z = z_centroid ("xy slice") and by the plane x = x_centroid ("yz slice").
#include <array>
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// An ordered chain of section points in a plane. Closed loops do not repeat the first point
// at the end; they are ordered counter-clockwise in their (u, v) coordinates.
struct Polyline {
  std::vector<std::array<double, 2>> points;
  bool closed = false;
};

struct CentralSlices {
  double theta = 0;              // inclination removed by the mapping (rad, (-pi/2, pi/2])
  Vec3 centroid = Vec3::Zero();  // volume centroid, in the mesh's own units (not scaled)
  // Section by z = z_centroid: points (u, v) = (x, y) relative to the centroid, after the mapping.
  std::vector<Polyline> xy;
  // Section by x = x_centroid: points (u, v) = (z, y) relative to the centroid, after the mapping,
  // so that y is the vertical coordinate of both slices (Figs. 41-53 draw them side by side).
  std::vector<Polyline> yz;
};

// Slices of `mesh` (closed, outward oriented) with every coordinate divided by `scale`
// (pass the capsule radius a to get units of a). A closed capsule gives one closed loop per
// plane; open chains (only for a surface with holes) are returned with closed = false.
// Vertices lying exactly on a cutting plane count as being on its positive side.
CentralSlices central_slices(const Mesh& mesh, double scale);

// A Mesh from the member file's raw arrays: xyz (n x 3, row-major) and triangles (n_tri x 3,
// outward oriented). Throws std::invalid_argument for inconsistent sizes or indices, and
// std::runtime_error (from build_topology) when the surface is not a closed 2-manifold.
Mesh mesh_from_arrays(const std::vector<double>& xyz, const std::vector<int>& triangles);

}  // namespace capsule::membrane3d
