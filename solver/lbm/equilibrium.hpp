#pragma once
// Maxwellian equilibrium (5): f_eq_i = w_i rho [1 + 3 c.u + 9/2 (c.u)^2 - 3/2 u.u].
#include <array>

namespace capsule::lbm {

template <class L>
void equilibrium(double rho, const std::array<double, 3>& u, double* feq) {
  double uu = 0.0;
  for (int a = 0; a < L::D; ++a) uu += u[a] * u[a];
  for (int i = 0; i < L::Q; ++i) {
    double cu = 0.0;
    for (int a = 0; a < L::D; ++a) cu += L::c[i][a] * u[a];
    const double w = double(L::weight_numerator[i]) / double(L::weight_denominator);
    feq[i] = w * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu);
  }
}

}  // namespace capsule::lbm
