#include "solver/scene/units.hpp"

#include <algorithm>
#include <stdexcept>

namespace capsule {

namespace {
// The relaxation-time rule (README "Relaxation time"). With Re = k a^2 / nu fixed, a larger
// nu means fewer steps per kt (steps_per_kt = a^2 / (Re nu)), but:
//  - accuracy: steady-state D_xy hardly depends on tau. Circle, a = 10, Ca = 0.05, E_b = 0.05,
//    D_xy at kt = 2.75: 0.274730 / 0.274729 / 0.274740 for tau = 0.7 / 1.0 / 1.5, area drift
//    -3e-6 / 3e-7 / -4e-5 (a = 5, E_b = 0: 0.39094 ... 0.39129 for tau = 0.6 ... 2.0, area drift
//    growing to -1.8e-3 at tau = 2). The resolution error (convergence study) is ~1e-3.
//  - stability of the explicit membrane coupling, governed by the membrane moduli over the
//    fluid viscosity: elastic S = E_s / nu = Re nu / (a Ca), bending B = E_B / (a^2 nu) * a
//    = E_b a Re nu / Ca. Measured with E_b = 0.05, Ca = 0.05: a = 5: tau = 2 (S = 0.10, B = 0.125)
//    runs, tau = 2.5 (S = 0.13, B = 0.17) blows up; a = 10: tau = 1.5 (S = 0.033, B = 0.17) runs,
//    tau = 2 (S = 0.05, B = 0.25) blows up; a = 20: tau = 1 (S = 0.008, B = 0.17) runs.
// Rule: tau = 1 (nu = 1/6), lowered until S <= 0.04 and B <= 0.12, never below 0.52.
// Membrane viscosity is not part of the rule (mu_s / nu = eta a does not depend on tau): the
// Kelvin-Voigt term (31) is taken implicitly in the node velocities and runs eta up to 20 at
// a = 10 (README "The 2D capsule").
double choose_tau_2d(const Scene& scene) {
  constexpr double nu_default = 1.0 / 6.0, S_max = 0.04, B_max = 0.12, tau_min = 0.52;
  double nu = std::min(nu_default, S_max * scene.a * scene.Ca / scene.Re);
  const double E_b = dimensionless_E_b(scene);
  if (E_b > 0) nu = std::min(nu, B_max * scene.Ca / (E_b * scene.a * scene.Re));
  return std::max(tau_min, 0.5 + 3.0 * nu);
}


// 3D: tau = 1 (nu = 1/6). A larger tau is cheaper (a^2/(Re nu) steps per kt) but tau = 2 went
// unstable (NaN at kt = 0.7, sphere, a = 5, Ca = 0.1) where tau = 1 ran to steady state within
// 3 % of the reference (solver/membrane3d/README.md).
double choose_tau_3d(const Scene&) { return 1.0; }
}  // namespace

double dimensionless_E_b(const Scene& s) {
  // The text's 2D reading (Scene::E_b_2d): E_B = E_b a_text E_s with a_text = 0.5 in its units
  // of h = 0.05 (Sec. 2.4), so E_B / (a^2 E_s) = E_b / a_text = 2 E_b.
  if (s.dim == 2 && s.E_b_2d == "dissertation") return 2.0 * s.E_b;
  return s.E_b;
}

double choose_tau(const Scene& scene) {
  if (scene.tau > 0) return scene.tau;
  return scene.dim == 2 ? choose_tau_2d(scene) : choose_tau_3d(scene);
}

Units units_for(const Scene& s, double tau) {
  if (!(tau > 0.5)) throw std::invalid_argument("relaxation time must exceed 1/2, got " + std::to_string(tau));
  Units u;
  u.tau = tau;
  u.nu = (tau - 0.5) / 3.0;                  // (8), (13)
  u.shear_rate = s.Re * u.nu / (s.a * s.a);  // Re = k a^2 / nu
  u.E_s = u.nu * u.shear_rate * s.a / s.Ca;  // (34) with mu_a = rho nu, rho = 1
  // (35) prints E_b = E_B / (a E_s), which is not dimensionless (E_B is an energy, E_s an
  // energy per area) and would make the physics depend on the resolution a. Sui et al.
  // (2008), whom Sec. 2.4.2 validates against with the same E_b values, use E_B / (a^2 E_s).
  u.E_B = dimensionless_E_b(s) * s.a * s.a * u.E_s;
  u.mu_s = s.eta * s.a * u.nu;               // (36)
  u.nu_inside = s.V * u.nu;
  u.steps_per_kt = 1.0 / u.shear_rate;
  return u;
}

}  // namespace capsule
