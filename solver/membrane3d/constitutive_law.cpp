#include "solver/membrane3d/constitutive_law.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace capsule::membrane3d {

double law_modulus(ElasticLaw law, double E_s) { return law == ElasticLaw::neo_hookean ? E_s / 3.0 : E_s; }

double Constitutive::energy_density(const Mat2& Cg) const {
  const double tr = Cg.trace(), det = Cg.determinant();
  if (law == ElasticLaw::neo_hookean) return 0.5 * E_s * (tr + 1.0 / det - 3.0);  // (56)
  const double I1 = tr - 2.0, I2 = det - 1.0;
  return 0.25 * E_s * (I1 * I1 + 2.0 * I1 - 2.0 * I2 + C * I2 * I2);
}

Mat2 Constitutive::second_piola_kirchhoff(const Mat2& Cg) const {
  const double det = Cg.determinant();
  const Mat2 Cinv = Cg.inverse();
  if (law == ElasticLaw::neo_hookean) return E_s * (Mat2::Identity() - Cinv / det);
  const double I1 = Cg.trace() - 2.0, I2 = det - 1.0;
  return E_s * ((I1 + 1.0) * Mat2::Identity() + det * (C * I2 - 1.0) * Cinv);
}

std::pair<double, double> Constitutive::principal_cauchy(double l1, double l2) const {
  const double J = l1 * l2;
  if (law == ElasticLaw::neo_hookean) {
    return {E_s / J * (l1 * l1 - 1.0 / (J * J)), E_s / J * (l2 * l2 - 1.0 / (J * J))};  // (58)-(59)
  }
  return {E_s / J * (l1 * l1 * (l1 * l1 - 1.0) + C * J * J * (J * J - 1.0)),   // (60)
          E_s / J * (l2 * l2 * (l2 * l2 - 1.0) + C * J * J * (J * J - 1.0))};  // (61)
}

}  // namespace capsule::membrane3d
