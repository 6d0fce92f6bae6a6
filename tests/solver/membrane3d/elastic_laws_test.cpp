// Each 3D membrane law (solver/membrane3d/laws/) under a uniaxial stretch lambda of one element
// (F = diag(lambda, 1), C = diag(lambda^2, 1), J = lambda) against its closed form, and the law
// picked by name.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/membrane3d/constitutive_law.hpp"

using namespace capsule::membrane3d;

namespace {

Mat2 uniaxial_C(double lambda) { return Mat2(Eigen::Vector2d(lambda * lambda, 1.0).asDiagonal()); }

// The Cauchy tensions sigma = F S F^T / J of the law's S along and across the stretch.
template <class Law>
std::pair<double, double> pushed_forward(const Law& law, double lambda) {
  const Mat2 S = law.second_piola_kirchhoff(uniaxial_C(lambda));
  CHECK(std::abs(S(0, 1)) < 1e-15);
  CHECK(std::abs(S(1, 0)) < 1e-15);
  return {lambda * lambda * S(0, 0) / lambda, S(1, 1) / lambda};
}

// sigma_1 = (1 / lambda_2) dW / dlambda_1 at lambda_2 = 1, by central differences.
template <class Law>
double energy_tension(const Law& law, double lambda) {
  const double h = 1e-6;
  return (law.energy_density(uniaxial_C(lambda + h)) - law.energy_density(uniaxial_C(lambda - h))) / (2 * h);
}

}  // namespace

TEST_CASE("neo-Hookean law: a uniaxial stretch gives E_s/lambda (lambda^2 - 1/lambda^2) (58)", "[membrane3d]") {
  const NeoHookean law{2.5};
  for (double lambda : {0.8, 1.0, 1.3, 2.0}) {
    INFO("lambda " << lambda);
    const double along = law.E_s / lambda * (lambda * lambda - 1.0 / (lambda * lambda));  // (58), l2 = 1
    const double across = law.E_s / lambda * (1.0 - 1.0 / (lambda * lambda));              // (59), l2 = 1
    const double W = 0.5 * law.E_s * (lambda * lambda + 1.0 + 1.0 / (lambda * lambda) - 3.0);  // (56)
    const auto [s1, s2] = pushed_forward(law, lambda);
    CHECK(s1 == Approx(along).margin(1e-14));
    CHECK(s2 == Approx(across).margin(1e-14));
    const auto [p1, p2] = law.principal_cauchy(lambda, 1.0);
    CHECK(p1 == Approx(along).margin(1e-14));
    CHECK(p2 == Approx(across).margin(1e-14));
    CHECK(law.energy_density(uniaxial_C(lambda)) == Approx(W).margin(1e-14));
    CHECK(energy_tension(law, lambda) == Approx(along).margin(1e-8));  // h^2 truncation
  }
  CHECK(NeoHookean::formula_modulus(3.0) == 1.0);  // G_s = E_s / 3 (docs/conventions.md)
}

TEST_CASE("Skalak law: a uniaxial stretch gives E_s lambda (1 + C)(lambda^2 - 1) (60)", "[membrane3d]") {
  const Skalak law{1.7, 10.0};
  for (double lambda : {0.8, 1.0, 1.3, 2.0}) {
    INFO("lambda " << lambda);
    const double e = lambda * lambda - 1.0;
    const double along = law.E_s * lambda * (1.0 + law.C) * e;  // (60), l2 = 1: I1 = I2 = lambda^2 - 1
    const double across = law.E_s * lambda * law.C * e;         // (61), l2 = 1
    const double W = 0.25 * law.E_s * (1.0 + law.C) * e * e;    // (57) with the standard I1
    const auto [s1, s2] = pushed_forward(law, lambda);
    CHECK(s1 == Approx(along).margin(1e-13));
    CHECK(s2 == Approx(across).margin(1e-13));
    const auto [p1, p2] = law.principal_cauchy(lambda, 1.0);
    CHECK(p1 == Approx(along).margin(1e-13));
    CHECK(p2 == Approx(across).margin(1e-13));
    CHECK(law.energy_density(uniaxial_C(lambda)) == Approx(W).margin(1e-13));
    CHECK(energy_tension(law, lambda) == Approx(along).margin(1e-7));  // h^2 truncation
  }
  CHECK(Skalak::formula_modulus(3.0) == 3.0);  // E_s as printed
}

TEST_CASE("the law picked by name is that law, with its parameters", "[membrane3d]") {
  const Mat2 C = uniaxial_C(1.4);
  const Constitutive neo{ElasticLaw::neo_hookean, 2.0, 7.0}, skalak{ElasticLaw::skalak, 2.0, 7.0};
  CHECK(neo.second_piola_kirchhoff(C) == NeoHookean{2.0}.second_piola_kirchhoff(C));
  CHECK(skalak.second_piola_kirchhoff(C) == Skalak{2.0, 7.0}.second_piola_kirchhoff(C));
  CHECK(neo.energy_density(C) == NeoHookean{2.0}.energy_density(C));
  CHECK(skalak.energy_density(C) == Skalak{2.0, 7.0}.energy_density(C));
  CHECK(law_modulus(ElasticLaw::neo_hookean, 3.0) == 1.0);
  CHECK(law_modulus(ElasticLaw::skalak, 3.0) == 3.0);
  CHECK(capsule::choice_from_name<ElasticLaw>("skalak") == ElasticLaw::skalak);
}
