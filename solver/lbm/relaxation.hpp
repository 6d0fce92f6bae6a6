#pragma once
// Relaxation rates of the MRT collision (docs/guide/model.md "Fluid", Sec. 2.1).
//  - shear moments: nu = (1/s_nu - 1/2)/3  (8), (13);
//  - heat-flux moments: (9) in D2Q9, s_q = s_nu in D3Q19;
//  - energy e: the bulk viscosity is tied to the shear viscosity by s_e = s_nu,
//    i.e. xi = nu/2 in D2Q9 by (10) and xi = 2 nu/3 in D3Q19 by (14) (the text
//    gives no value of xi). s_e = s_nu makes plane Couette flow exact (the tests demand
//    1e-8): any other s_e leaves a steady O(U^2) error (measured |du|/U = 1.1e-3 U for
//    s_e = 1.64, H = 8, tau = 1);
//  - energy square eps: ALSO s_nu (RateGroup::energy), where the text says 1.64 (D2Q9)
//    and 1.8 (D3Q19). Reason: with s_e = s_nu and s_eps fixed near 2 the scheme is
//    linearly unstable at rest once tau = 1/s_nu exceeds ~1.9 in D2Q9 (nu ~ 0.47) and
//    ~1.5 in D3Q19 (nu ~ 0.33, i.e. V ~ 2 at nu = 1/6). Von Neumann growth
//    factor per step, max over wave numbers: 1.011 / 1.081 / 1.159 / 1.206 at
//    tau = 2 / 3 / 5.5 / 10 in D2Q9, 1.034 / 1.097 / 1.185 / 1.243 in D3Q19, for u = 0
//    and likewise for |u| <= 0.1. It blew up the inner fluid of a viscosity-ratio-5
//    inclusion (nu = 5/6, tau = 3) within ~430 steps; a uniform nu = 5/6 Couette flow
//    survived only because an x-uniform flow never seeds the (2D) unstable mode. With
//    s_eps = s_e = s_nu the same analysis gives max |lambda| <= 1 + 1e-14 at
//    tau = 0.52, 0.6, 1, 2, 3, 5.5, 10 and u = 0, 0.02, 0.1 (x), 0.07 (diagonal), in
//    both lattices. Keeping the text's s_eps and fixing s_e too (e.g. 1.64) is stable
//    for tau >= 0.6 as well, but gives up the exact Couette flow. eps enters no hydrodynamic
//    term at Navier-Stokes order (Sec. 2.1 says as much), so nu is unchanged;
//    tests/solver/lbm/viscosity_contrast_stability_test.cpp and two_layer_couette_test.cpp
//    check ratios 5 and 10;
//  - the remaining higher-order moments: L::fixed_rate (none in D2Q9; pi and m at 1.8
//    in D3Q19).
// These are the rates of CollisionModel::mrt, the default. CollisionModel::trt (scene key
// `resolution.collision`) is the two-relaxation-time collision (Ginzburg): every even
// non-conserved moment at s_nu (as above: stresses, e, eps, and now also D3Q19's pi), every
// odd one (q, and D3Q19's m) at s_minus with the "magic" product
//   Lambda = (1/s_nu - 1/2)(1/s_minus - 1/2) = 3/16
// at every node. Why: with the MRT rates the odd moments' Lambda is (1/s_nu - 1/2)^2 for q,
// so it grows with the node's viscosity, and the steady Stokes solution of the lattice
// Boltzmann scheme depends on Lambda (Ginzburg & d'Humieres 2003; Ginzburg, Verhaeghe &
// d'Humieres 2008): inside a capsule V times more viscous, Lambda = (3 V nu)^2 moves the
// solution with tau. With Lambda fixed, the solution of given physical numbers is the same
// for every tau. 3/16 is the value for which half-way bounce-back puts a Poiseuille wall
// exactly half-way; measured in docs/findings/accuracy_and_stability.md "Viscosity contrast
// and the relaxation time".
#include <stdexcept>
#include <string>

#include "solver/lbm/lattice.hpp"

namespace capsule::lbm {

enum class CollisionModel { mrt, trt };
// The scene's resolution.collision: "mrt" or "trt".
inline CollisionModel collision_from_name(const std::string& name) {
  if (name == "mrt") return CollisionModel::mrt;
  if (name == "trt") return CollisionModel::trt;
  throw std::invalid_argument("unknown collision model \"" + name + "\" (mrt, trt)");
}

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
