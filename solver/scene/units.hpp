#pragma once
// From dimensionless groups to lattice units (dx = dt = rho = 1), CONTRACTS.md.
#include "solver/scene/scene.hpp"

namespace capsule {

struct Units {
  double tau = 0;          // relaxation time of the ambient fluid
  double nu = 0;           // ambient kinematic viscosity = mu_a (rho = 1), (8)/(13)
  double shear_rate = 0;   // k = Re nu / a^2
  double E_s = 0;          // shear modulus, Ca = mu_a k a / E_s (34)
  double E_B = 0;          // bending modulus, E_b = E_B / (a^2 E_s) (35) made dimensionless (docs/conventions.md "E_b")
  double mu_s = 0;         // membrane viscosity, eta = mu_s / (a mu_a) (36)
  double nu_inside = 0;    // V nu
  double steps_per_kt = 0; // 1 / k
};

// E_B / (a^2 E_s) of the scene: its E_b, or 2 E_b for a 2D scene in the dissertation's
// convention (Scene::E_b_2d).
double dimensionless_E_b(const Scene& scene);

// tau must be > 1/2; throws std::invalid_argument otherwise.
Units units_for(const Scene& scene, double tau);

// The relaxation time the solver runs a scene with: the scene's tau, or when it is 0 the
// rule of docs/guide/model.md "Relaxation time" (stability of the explicit membrane coupling).
double choose_tau(const Scene& scene);

}  // namespace capsule
