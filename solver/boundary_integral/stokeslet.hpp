#pragma once
// The free-space Stokeslet (Oseen tensor) of unbounded Stokes flow:
//   G_ij(r) = delta_ij / |r| + r_i r_j / |r|^3,   u(x) = (1/(8 pi mu)) G(x - y) F
// is the velocity at x of a point force F at y in a fluid of viscosity mu (Pozrikidis 1992,
// "Boundary integral and singularity methods", (2.2.8)-(2.2.9)).
#include <Eigen/Dense>

namespace capsule::boundary_integral {

using Vec3 = Eigen::Vector3d;

// G(r) F for r != 0.
inline Vec3 stokeslet_apply(const Vec3& r, const Vec3& F) {
  const double r2 = r.squaredNorm();
  const double inv_r = 1.0 / std::sqrt(r2);
  return inv_r * (F + r * (r.dot(F) / r2));
}

// G is even and homogeneous of degree -1, G(s w) = G(w)/|s|: on a Duffy map from the target
// (y - x = u w) the Jacobian's factor u cancels the 1/u and the integrand is smooth.

}  // namespace capsule::boundary_integral
