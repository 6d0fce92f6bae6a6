#pragma once
// FEM membrane elasticity (Sec. 2.5.1, (42)-(55)) with linear triangles, and the
// standard-linear-solid membrane viscoelasticity (63)-(67).
//
// Per triangle, the reference edges are written in a plane frame of the reference triangle
// (Charrier: vertex i at the origin, edge ij along the local x axis), giving the 2x2 shape
// matrix D_m whose inverse holds the shape-function gradients (50)-(54). The current edges
// (3x2, E_s = [X_j - X_i, X_k - X_i]) give F = E_s D_m^-1 (3x2) and C = F^T F (2x2); since
// C is invariant under rigid motion, mapping the current triangle to the plane is implicit.
// The nodal force (55) is f_l = -A_0 P grad N^l with the first Piola-Kirchhoff tension
// P = F S = J sigma F^-T: (55)'s (lambda1 lambda2 / 2) sigma F^-T [a; b] with A_0 = (a_i x_i + ...)/2.
// The sign is that of the force the membrane exerts on its nodes (minus the energy gradient),
// i.e. the force handed to the fluid.
#include <array>
#include <vector>

#include "solver/membrane3d/constitutive_law.hpp"
#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

// Standard linear solid (docs/conventions.md "Membrane viscosity in 3D"): a Maxwell element (modulus E_m = G E_s, relaxation time
// tau_m = mu_s / E_m -- the text's "tau_m = E_m / mu_s" has the wrong dimension) in parallel
// with the elastic law. Its tension is the relaxation-weighted history of the Maxwell
// element's instantaneous elastic tension S_m(C) (the law with E_s -> E_m; Skalak's law without
// its area term, C = 0: a shear viscosity, the area constant the elastic branch's alone):
//   Q(t) = int_0^t exp(-(t - s)/tau_m) d S_m(C(s))/ds ds,
// updated in O(1) per step by (67) with S_m varying linearly over a step:
//   Q_{n+1} = exp(-dt/tau_m) Q_n + tau_m (S_m(n+1) - S_m(n))/dt (1 - exp(-dt/tau_m)).
// In 2nd Piola-Kirchhoff form this is (63)-(64) (the g_0 F F^T and pressure terms are the
// neo-Hookean S = E_s (I - C^-1/det C) pushed forward). For a fast Maxwell element
// (tau_m << 1/k) the membrane is Kelvin-Voigt with surface shear viscosity mu_s = E_m tau_m.
//
// Power-law surface viscosity (Sec. 5.2, (101)-(102), taken into the membrane): the surface
// viscosity of triangle t follows its own surface shear rate gamma_t (surface_shear_rate.hpp),
// mu_s(gamma_t) = mu_s(k) (gamma_t / k)^(n - 1) with gamma_t / k floored at gamma_floor (a rigid
// motion has gamma = 0, where mu_s diverges for n < 1), and with it its relaxation time,
// tau_t = mu_s(gamma_t) / E_m = tau_m (gamma_t / k)^(n - 1): tau_m is the one at gamma = k.
// n = 1 is the plain standard linear solid, step for step.
struct PowerLawRelaxation {
  bool on = false;
  double n = 1;               // flow behaviour index (102)
  double shear_rate = 0;      // k (per time step): gamma is measured in units of k
  double gamma_floor = 0.01;  // smallest gamma / k used in (102)
};

struct MaxwellElement {
  double E_m = 0;    // 0: purely elastic
  double tau_m = 0;  // relaxation time (time steps); with a power law, the one at gamma = k
  double dt = 1;     // time step
  PowerLawRelaxation power_law = {};
  // Skalak's area term (C) in the element too: physics version 5's (the law as it is). Off, the
  // element is a shear viscosity and the area constant the elastic branch's alone.
  bool skalak_area_term = false;
};

class ElasticMembrane {
 public:
  ElasticMembrane() = default;
  // `reference` fixes the stress-free shape of every triangle (it may differ from the start
  // shape: Table 1 case C).
  ElasticMembrane(const Mesh& reference, const Constitutive& law, const MaxwellElement& maxwell = {});

  // Adds the elastic (and viscoelastic) nodal forces for the current positions to `force`.
  // With a Maxwell element this ADVANCES its memory by one step (call once per time step).
  void add_forces(const Mesh& current, std::vector<Vec3>& force);
  // The same forces without touching the viscoelastic memory.
  void add_elastic_forces(const Mesh& current, std::vector<Vec3>& force) const;
  // Stored elastic energy sum_t A_0 W(C_t) (the elastic branch only).
  double energy(const Mesh& current) const;

  // Right Cauchy-Green tensor of triangle t (reference frame).
  Mat2 cauchy_green(const Mesh& current, int t) const;
  double reference_area(int t) const { return area0_[t]; }
  double reference_total_area() const;
  const Constitutive& law() const { return law_; }

  // The surface shear rate gamma_t / k of every triangle over the last step (power law only;
  // empty before the first step).
  const std::vector<double>& surface_shear_rates() const { return gamma_; }

  // Restart points: the SLS memory (Q and S_m of the last step per triangle, 2x2 each, flat
  // column-major, 8 numbers per triangle, 12 with a power law (and C of the last step); empty
  // before the first step or without SLS).
  std::vector<double> memory() const;
  bool memory_started() const { return memory_started_; }
  void restore_memory(const std::vector<double>& flat, bool started);  // throws on a size mismatch

 private:
  Constitutive law_;
  MaxwellElement maxwell_;
  std::vector<Mat2> Dm_inv_;
  std::vector<double> area0_;
  std::vector<Mat2> Q_, Sm_previous_;  // SLS memory per triangle
  std::vector<Mat2> C_previous_;       // power law: C of the last step per triangle
  std::vector<double> gamma_;          // power law: gamma_t / k of the last step
  bool memory_started_ = false;
  // The three corner forces of each triangle, kept between steps so a step allocates nothing
  // (a fresh 360 KB vector per step cost page faults at level 4).
  mutable std::vector<std::array<Vec3, 3>> tri_force_;

  void add_power_law_forces(const Mesh& current, std::vector<Vec3>& force);
  template <class TensionFn>
  void accumulate(const Mesh& current, std::vector<Vec3>& force, TensionFn&& tension) const;
};

}  // namespace capsule::membrane3d
