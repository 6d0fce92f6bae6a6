#pragma once
// The Skalak membrane law (Sec. 2.5.2), I1 = l1^2 + l2^2 - 2, I2 = l1^2 l2^2 - 1:
//   W = E_s/4 (I1^2 + 2 I1 - 2 I2 + C I2^2)                           (57)
//   S = 2 dW/dC = E_s [(I1 + 1) I + det C (C I2 - 1) C^-1]
//   tau_i = E_s/(l1 l2) (l_i^2 (l_i^2 - 1) + C (l1 l2)^2 ((l1 l2)^2 - 1))   (60)-(61)
// (57) prints (l1 + l2 - 2) where I1 belongs: that misprint does not give (60)-(61), the
// standard Skalak form does (tests/solver/membrane3d). E_s is the E_s of Ca (34) as printed.
#include "solver/membrane3d/laws/hyperelastic_law.hpp"

namespace capsule::membrane3d {

struct Skalak {
  double E_s = 1;
  double C = 15;  // area-dilation constant

  static double formula_modulus(double E_s_of_Ca) { return E_s_of_Ca; }
  double energy_density(const Mat2& Cg) const;
  Mat2 second_piola_kirchhoff(const Mat2& Cg) const;
  std::pair<double, double> principal_cauchy(double lambda1, double lambda2) const;
};
static_assert(HyperelasticLaw<Skalak>);

}  // namespace capsule::membrane3d
