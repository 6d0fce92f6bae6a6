#include "solver/membrane3d/constitutive_law.hpp"

namespace capsule::membrane3d {

double law_modulus(ElasticLaw law, double E_s) {
  return visit_law(Constitutive{law, E_s}, [E_s]<class Law>(const Law&) { return Law::formula_modulus(E_s); });
}

double Constitutive::energy_density(const Mat2& Cg) const {
  return visit_law(*this, [&](const auto& law) { return law.energy_density(Cg); });
}

Mat2 Constitutive::second_piola_kirchhoff(const Mat2& Cg) const {
  return visit_law(*this, [&](const auto& law) { return law.second_piola_kirchhoff(Cg); });
}

std::pair<double, double> Constitutive::principal_cauchy(double l1, double l2) const {
  return visit_law(*this, [&](const auto& law) { return law.principal_cauchy(l1, l2); });
}

}  // namespace capsule::membrane3d
