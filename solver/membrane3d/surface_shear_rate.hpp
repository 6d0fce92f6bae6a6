#pragma once
// The membrane's own surface shear rate (101), per triangle, from its right Cauchy-Green tensor
// C = F^T F (reference frame, elasticity.hpp) at two times dt apart.
//
// The surface rate of deformation of the current triangle is D_s = F^+T (dC/dt / 2) F^+ with
// F^+ = C^-1 F^T, so tr(D_s^2) = tr(C^-1 C' C^-1 C') / 4 and (101) gamma = sqrt(2 tr D_s^2) =
// sqrt(tr(A A) / 2), A = C^-1 C'. This is (100)'s P grad U P for the velocity the membrane
// itself moves with (it includes the area dilation rate, as (100) does), without the lattice
// gradient (99): a rigid motion gives exactly 0, and a planar simple shear of rate s gives s.
// C' is the backward difference (C - C_previous) / dt, C taken at the midpoint for C^-1.
#include <algorithm>
#include <cmath>

#include "solver/membrane3d/constitutive_law.hpp"

namespace capsule::membrane3d {

inline double surface_shear_rate(const Mat2& C_previous, const Mat2& C, double dt) {
  const Mat2 rate = (C - C_previous) / dt;
  const Mat2 A = (0.5 * (C + C_previous)).inverse() * rate;
  return std::sqrt(0.5 * std::max(0.0, (A * A).trace()));
}

}  // namespace capsule::membrane3d
