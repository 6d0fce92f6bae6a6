#include "solver/membrane3d/laws/neo_hookean.hpp"

#include <Eigen/LU>

namespace capsule::membrane3d {

double NeoHookean::energy_density(const Mat2& Cg) const {
  const double tr = Cg.trace(), det = Cg.determinant();
  return 0.5 * E_s * (tr + 1.0 / det - 3.0);  // (56)
}

Mat2 NeoHookean::second_piola_kirchhoff(const Mat2& Cg) const {
  const double det = Cg.determinant();
  const Mat2 Cinv = Cg.inverse();
  return E_s * (Mat2::Identity() - Cinv / det);
}

std::pair<double, double> NeoHookean::principal_cauchy(double l1, double l2) const {
  const double J = l1 * l2;
  return {E_s / J * (l1 * l1 - 1.0 / (J * J)), E_s / J * (l2 * l2 - 1.0 / (J * J))};  // (58)-(59)
}

}  // namespace capsule::membrane3d
