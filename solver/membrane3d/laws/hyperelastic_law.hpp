#pragma once
// What every 3D membrane law provides (Sec. 2.5.2): a hyperelastic energy per reference area in
// the right Cauchy-Green tensor C = F^T F of the in-plane deformation (2x2, reference frame), so
// that no eigen-decomposition is needed (l1^2 + l2^2 = tr C, l1^2 l2^2 = det C). One law per
// file beside this one; solver/membrane3d/constitutive_law.hpp picks one by name, once.
#include <Eigen/Core>
#include <concepts>
#include <utility>

namespace capsule::membrane3d {

using Mat2 = Eigen::Matrix2d;

template <class Law>
concept HyperelasticLaw = requires(Law law, const Mat2& C, double stretch) {
  law.E_s = stretch;                                            // the modulus the formulas take
  { law.energy_density(C) } -> std::convertible_to<double>;    // W per reference area
  { law.second_piola_kirchhoff(C) } -> std::same_as<Mat2>;     // S = 2 dW/dC
  { law.principal_cauchy(stretch, stretch) } -> std::same_as<std::pair<double, double>>;
  { Law::formula_modulus(stretch) } -> std::convertible_to<double>;  // from the E_s of Ca (34)
};

}  // namespace capsule::membrane3d
