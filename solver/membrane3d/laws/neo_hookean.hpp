#pragma once
// The neo-Hookean membrane law (Sec. 2.5.2):
//   W = E_s/2 (l1^2 + l2^2 + 1/(l1^2 l2^2) - 3)                      (56)
//   S = 2 dW/dC = E_s (I - C^-1 / det C)
//   tau_i = E_s/(l1 l2) (l_i^2 - 1/(l1 l2)^2)                          (58)-(59)
// E_s here is a third of the E_s of Ca (34): the small-deformation shear modulus G_s of
// Ramanujan and Pozrikidis' "surface modulus of elasticity" (docs/conventions.md
// "Neo-Hookean modulus").
#include "solver/membrane3d/laws/hyperelastic_law.hpp"

namespace capsule::membrane3d {

struct NeoHookean {
  double E_s = 1;

  static double formula_modulus(double E_s_of_Ca) { return E_s_of_Ca / 3.0; }
  double energy_density(const Mat2& C) const;
  Mat2 second_piola_kirchhoff(const Mat2& C) const;
  std::pair<double, double> principal_cauchy(double lambda1, double lambda2) const;
};
static_assert(HyperelasticLaw<NeoHookean>);

}  // namespace capsule::membrane3d
