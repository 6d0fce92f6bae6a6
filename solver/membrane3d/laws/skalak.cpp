#include "solver/membrane3d/laws/skalak.hpp"

#include <Eigen/LU>

namespace capsule::membrane3d {

double Skalak::energy_density(const Mat2& Cg) const {
  const double tr = Cg.trace(), det = Cg.determinant();
  const double I1 = tr - 2.0, I2 = det - 1.0;
  return 0.25 * E_s * (I1 * I1 + 2.0 * I1 - 2.0 * I2 + C * I2 * I2);  // (57), I1 standard
}

Mat2 Skalak::second_piola_kirchhoff(const Mat2& Cg) const {
  const double det = Cg.determinant();
  const Mat2 Cinv = Cg.inverse();
  const double I1 = Cg.trace() - 2.0, I2 = det - 1.0;
  return E_s * ((I1 + 1.0) * Mat2::Identity() + det * (C * I2 - 1.0) * Cinv);
}

std::pair<double, double> Skalak::principal_cauchy(double l1, double l2) const {
  const double J = l1 * l2;
  return {E_s / J * (l1 * l1 * (l1 * l1 - 1.0) + C * J * J * (J * J - 1.0)),   // (60)
          E_s / J * (l2 * l2 * (l2 * l2 - 1.0) + C * J * J * (J * J - 1.0))};  // (61)
}

}  // namespace capsule::membrane3d
