#pragma once
// Relaxation rates of the MRT collision (DESIGN 3.1, Sec. 2.1).
//  - shear moments: nu = (1/s_nu - 1/2)/3  (8), (13);
//  - heat-flux moments: (9) in D2Q9, s_q = s_nu in D3Q19;
//  - energy e: the bulk viscosity is tied to the shear viscosity by s_e = s_nu,
//    i.e. xi = nu/2 in D2Q9 by (10) and xi = 2 nu/3 in D3Q19 by (14) (the text
//    gives no value of xi; s_e = s_nu keeps every rate a function of the node's nu);
//  - the remaining higher-order moments: L::fixed_rate (1.64 in D2Q9, 1.8 in D3Q19).
#include "solver/lbm/lattice.hpp"

namespace capsule::lbm {

// (8)/(13) solved for s_nu.
constexpr double shear_rate_from_viscosity(double nu) { return 1.0 / (3.0 * nu + 0.5); }
// (8)/(13).
constexpr double viscosity_from_shear_rate(double s_nu) { return (1.0 / s_nu - 0.5) / 3.0; }

// Rate of moment k given the node's s_nu (k, group known at compile time in the kernel).
template <class L>
constexpr double relaxation_rate(RateGroup g, double s_nu) {
  switch (g) {
    case RateGroup::shear: return s_nu;
    case RateGroup::energy: return s_nu;
    case RateGroup::heat_flux: return L::heat_flux_rate(s_nu);
    case RateGroup::fixed: return L::fixed_rate;
    case RateGroup::conserved: return 0.0;
  }
  return 0.0;
}

}  // namespace capsule::lbm
