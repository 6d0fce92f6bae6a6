#pragma once
// Shape measures written every output interval (docs/guide/member-files.md "3D series"): the Taylor deformation of the
// inertia-equivalent ellipsoid (37)-(38), the extent-based deformation of the shear-plane
// section, inclination, and mesh health.
#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// Centroid of the enclosed volume.
Vec3 volume_centroid(const Mesh& mesh);

struct InertiaDeformation {
  double D = 0;       // (L - W)/(L + W) (37)
  double theta = 0;   // inclination of the major axis to the x axis, in (-pi/2, pi/2]
  double L = 0, W = 0;  // full axes of the inertia-equivalent ellipse in the xy-plane
  Vec3 centroid = Vec3::Zero();
};
// (38) evaluated exactly for the polyhedron (second moments of the signed tetrahedra from
// the centroid). An ellipsoid with semi-axes A, B, C has second moments V A^2/5 etc., so the
// semi-axes in the shear plane are sqrt(5 mu / V) for the eigenvalues mu of the xy-block of
// the second-moment tensor (the inertia tensor is I = tr(M) 1 - M). In shear flow z is a
// principal axis (symmetry), where this equals the equivalent ellipsoid's axes in the xy-plane.
InertiaDeformation inertia_deformation(const Mesh& mesh);

// (r_max - r_min)/(r_max + r_min) for the section of the surface by the plane z = centre.z():
// r is the distance in the xy-plane from the centre to the section polygon (r_min: the
// nearest point of its segments; r_max: the farthest). Ramanujan and Pozrikidis' measure.
double extent_deformation(const Mesh& mesh, const Vec3& centre);

// Smallest triangle quality 4 sqrt(3) A / (l1^2 + l2^2 + l3^2) (1: equilateral, 0: degenerate).
double min_triangle_quality(const Mesh& mesh);

}  // namespace capsule::membrane3d
