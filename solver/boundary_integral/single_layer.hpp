#pragma once
// The single-layer potential of a closed triangulated surface (Pozrikidis 1992, (5.3.8)):
//   u(x) = (1/(8 pi mu)) int_S G(x - y) q(y) dS(y),
// the velocity that a force density q (force per area, exerted ON the fluid) spread on S gives
// in unbounded Stokes flow. For a capsule whose inner and outer viscosities are equal (V = 1)
// this is the whole disturbance of the imposed flow: u = u_inf + u_q is exact, with no
// double layer (Pozrikidis 1992, Sec. 5.3; Ramanujan and Pozrikidis 1998, (2.3)).
//
// Discretisation: q is linear on every triangle between its vertex values. At a vertex x_i
// the integral is split by distance:
//   - triangles having x_i as a corner (the 1/r singularity): Duffy's map from x_i,
//     y = x_i + u [(x_j - x_i) + v (x_k - x_j)], dS = 2 A u du dv, which cancels the 1/r;
//     an n x n Gauss-Legendre rule on the unit square (n = singular_gauss_points);
//   - triangles whose centroid lies within max(near_factor x longest edge, near_radius) of
//     x_i: the same map from the corner nearest to x_i, n = near_gauss_points;
//   - all others: the vertex (trapezoid) rule, exact for linear integrands, so their sum is
//     that of point forces q_j A_j at the vertices (A_j a third of the incident triangles'
//     areas).
// The near zone has a fixed radius as well as one in edges: the trapezoid rule's error on a
// triangle at distance d is O(h^2/d^2) of its share, which summed from d_min outwards is
// O(h^2/d_min); a zone of a few edges only (d_min ~ h) would leave a first-order error
// (measured: the exact single layers of tests/solver/boundary_integral stall at 0.6-1 % from
// level 2 to 4 with a zone of one edge).
// Each target is independent: the result does not depend on the thread count.
#include <vector>

#include "solver/boundary_integral/stokeslet.hpp"
#include "solver/membrane3d/mesh.hpp"

namespace capsule::boundary_integral {

struct SingleLayerOptions {
  int singular_gauss_points = 8;  // n of the n x n rule on a triangle with the target as a corner
  int near_gauss_points = 4;      // the same on the other near triangles
  double near_factor = 2.5;       // near: centroid distance < near_factor x longest edge ...
  double near_radius = 0.5;       // ... or < near_radius (lengths of the surface, e.g. a = 1)
  double viscosity = 1;       // mu
};

class SingleLayer {
 public:
  explicit SingleLayer(SingleLayerOptions options = {});

  // u_i = (1/(8 pi mu)) int G(x_i - y) q(y) dS(y) at every vertex; q given per vertex.
  void velocity(const membrane3d::Mesh& mesh, const std::vector<Vec3>& q, std::vector<Vec3>& u) const;

  const SingleLayerOptions& options() const { return options_; }

 private:
  SingleLayerOptions options_;
  std::vector<double> singular_nodes_, singular_weights_, near_nodes_, near_weights_;  // Gauss-Legendre on [0, 1]
};

// A third of the incident triangles' areas at every vertex (the trapezoid rule's weights).
std::vector<double> lumped_vertex_areas(const membrane3d::Mesh& mesh);

// dV/dx_j of the enclosed volume: (1/3) sum over incident triangles of A_t n_t.
std::vector<Vec3> volume_gradient(const membrane3d::Mesh& mesh);

// Removes from u the component along the volume gradient, u -= lambda g with
// lambda = sum u.g / sum g.g, so that the discrete volume has zero rate of change. The
// single layer conserves volume exactly; its discretisation does not, and the leak would
// accumulate over a long shear (Ramanujan and Pozrikidis 1998 correct it the same way).
// Returns lambda (the removed flux, for diagnostics).
double remove_volume_flux(const membrane3d::Mesh& mesh, std::vector<Vec3>& u);

}  // namespace capsule::boundary_integral
