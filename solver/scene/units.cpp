#include "solver/scene/units.hpp"

#include <stdexcept>

namespace capsule {

Units units_for(const Scene& s, double tau) {
  if (!(tau > 0.5)) throw std::invalid_argument("relaxation time must exceed 1/2, got " + std::to_string(tau));
  Units u;
  u.tau = tau;
  u.nu = (tau - 0.5) / 3.0;                  // (8), (13)
  u.shear_rate = s.Re * u.nu / (s.a * s.a);  // Re = k a^2 / nu
  u.E_s = u.nu * u.shear_rate * s.a / s.Ca;  // (34) with mu_a = rho nu, rho = 1
  u.E_B = s.E_b * s.a * u.E_s;               // (35)
  u.mu_s = s.eta * s.a * u.nu;               // (36)
  u.nu_inside = s.V * u.nu;
  u.steps_per_kt = 1.0 / u.shear_rate;
  return u;
}

}  // namespace capsule
