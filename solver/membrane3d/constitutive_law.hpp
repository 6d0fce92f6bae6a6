#pragma once
// Two-dimensional hyperelastic membrane laws (Sec. 2.5.2), written in the right
// Cauchy-Green tensor C = F^T F of the in-plane deformation (2x2, reference frame) so that
// no eigen-decomposition is needed: lambda_1^2 + lambda_2^2 = tr C, lambda_1^2 lambda_2^2 = det C.
#include <Eigen/Core>
#include <utility>

#include "solver/common/name_table.hpp"

namespace capsule::membrane3d {

using Mat2 = Eigen::Matrix2d;

enum class ElasticLaw { neo_hookean, skalak };
// The names of the scene's key `law` (3D) and of `capsule reference-bim --law`.
inline constexpr NameTable<ElasticLaw, 2> elastic_law_names{{{ElasticLaw::neo_hookean, "neo-hookean"},
                                                             {ElasticLaw::skalak, "skalak"}}};
constexpr const auto& name_table(ElasticLaw) { return elastic_law_names; }

// The modulus the law's formulas take (Constitutive::E_s) for the E_s of Ca = mu k a / E_s (34)
// (docs/conventions.md "Neo-Hookean modulus"): neo-Hookean E_s/3, the small-deformation shear
// modulus G_s of Ramanujan and Pozrikidis' "surface modulus of elasticity" E_s; Skalak E_s as
// printed.
double law_modulus(ElasticLaw law, double E_s);

struct Constitutive {
  ElasticLaw law = ElasticLaw::neo_hookean;
  double E_s = 1;  // shear modulus
  double C = 15;   // Skalak area-dilation constant

  // Energy per reference area.
  //  neo-Hookean (56): W = E_s/2 (l1^2 + l2^2 + 1/(l1^2 l2^2) - 3)
  //  Skalak: W = E_s/4 (I1^2 + 2 I1 - 2 I2 + C I2^2), I1 = l1^2 + l2^2 - 2, I2 = l1^2 l2^2 - 1.
  //  (57) prints (l1 + l2 - 2) where I1 belongs: that misprint does not give the stresses (60)-(61),
  //  the standard Skalak form does (checked in the tests).
  double energy_density(const Mat2& C) const;
  // Second Piola-Kirchhoff tension S = 2 dW/dC.
  //  neo-Hookean: S = E_s (I - C^-1 / det C)
  //  Skalak:      S = E_s [(I1 + 1) I + det C (C I2 - 1) C^-1]
  Mat2 second_piola_kirchhoff(const Mat2& C) const;
  // Principal Cauchy tensions as printed: (58)-(59) neo-Hookean, (60)-(61) Skalak.
  std::pair<double, double> principal_cauchy(double lambda1, double lambda2) const;
};

}  // namespace capsule::membrane3d
