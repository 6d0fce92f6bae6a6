#pragma once
// Relaxation rates of the MRT collision (Sec. 2.1; why each, measured: docs/guide/model.md "Fluid").
//  - the stresses at s_nu, nu = (1/s_nu - 1/2)/3 (8), (13);
//  - the heat fluxes q by (9) in D2Q9, at s_nu in D3Q19;
//  - the energy e at s_nu (bulk viscosity xi = nu/2 by (10), 2 nu/3 by (14): the text gives
//    none; any other s_e leaves a steady O(U^2) error in plane Couette flow);
//  - the energy square eps ALSO at s_nu, where the text fixes 1.64 / 1.8: with s_e = s_nu that
//    is linearly unstable at rest above tau ~ 1.9 (D2Q9) / 1.5 (D3Q19); eps enters no term at
//    Navier-Stokes order (tests/solver/lbm/viscosity_contrast_stability_test.cpp);
//  - the remaining moments at L::fixed_rate (D3Q19's pi and m at 1.8).
// CollisionModel::trt (scene key resolution.collision) is the two-relaxation-time collision
// (Ginzburg): every even non-conserved moment at s_nu, every odd one at s_minus with
//   Lambda = (1/s_nu - 1/2)(1/s_minus - 1/2) = 3/16
// at every node, so the steady solution of given physical numbers does not move with tau (with
// the MRT rates Lambda grows as (3 nu)^2 with a node's viscosity:
// docs/findings/accuracy_and_stability.md "Viscosity contrast and the relaxation time").
#include "solver/common/name_table.hpp"
#include "solver/lbm/lattice.hpp"

namespace capsule::lbm {

enum class CollisionModel { mrt, trt };
// The scene's resolution.collision.
inline constexpr NameTable<CollisionModel, 2> collision_names{{{CollisionModel::mrt, "mrt"}, {CollisionModel::trt, "trt"}}};
constexpr const auto& name_table(CollisionModel) { return collision_names; }

// TRT: the odd moments' rate from the node's s_nu, Lambda = trt_magic.
inline constexpr double trt_magic = 3.0 / 16.0;
template <class A>
constexpr A trt_odd_rate(A s_nu) {
  const A tp = A(1) / s_nu - A(0.5);  // 3 nu
  return tp / (A(0.5) * tp + A(trt_magic));
}

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
