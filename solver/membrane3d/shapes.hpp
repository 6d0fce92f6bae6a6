#pragma once
// Capsule shapes on the icosphere (Sec. 2.5): sphere, biconcave (39)-(41), the 45-degree
// inclination, and the reference configurations of Table 1.
#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// Biconcave shape parameter of (39)-(41).
inline constexpr double biconcave_alpha = 1.3858;

// Vertices of `unit` (an icosphere) scaled to a sphere of radius `radius` about the origin.
Mesh sphere_mesh(const Mesh& unit, double radius);

// Vertices of `unit` mapped to the biconcave surface (39)-(41) with symmetry axis y:
// the unit-sphere point (sin chi cos phi, cos chi, sin chi sin phi) goes to
// (s alpha sin chi cos phi, (s alpha / 2)(0.207 + 2.003 sin^2 chi - 1.123 sin^4 chi) cos chi,
//  s alpha sin chi sin phi), where the scale s makes the ANALYTIC volume of the shape equal
// to (4/3) pi a^3 ("equivalent radius" a).
Mesh biconcave_mesh(const Mesh& unit, double equivalent_radius);

// The scale s above for equivalent radius 1 (analytic volume of (39)-(41) with s = 1 by quadrature).
double biconcave_scale_for_unit_equivalent_radius();

// Rotates every vertex by `angle` (rad) about the z axis (counter-clockwise in the xy-plane)
// and then translates by `centre`.
void rotate_about_z_and_translate(Mesh& mesh, double angle, const Vec3& centre);

}  // namespace capsule::membrane3d
