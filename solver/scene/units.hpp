#pragma once
// From dimensionless groups to lattice units (dx = dt = rho = 1), CONTRACTS.md.
#include "solver/membrane2d/elastic_law.hpp"
#include "solver/membrane3d/constitutive_law.hpp"
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
// convention (SceneConventions::E_b_2d).
double dimensionless_E_b(const Scene& scene);

// The bending modulus of the membrane the solver builds: its nodes on the radius
// r_m = a - resolution.marker_inset, E_B = E_b r_m^2 E_s (E_b as dimensionless_E_b), the bending
// number of the circle or sphere the membrane is. Without an inset it is units.E_B.
double membrane_bending_modulus(const Scene& scene, const Units& units);

// tau must be > 1/2; throws std::invalid_argument otherwise.
Units units_for(const Scene& scene, double tau);

// The membrane's small-deformation shear modulus G_s from the E_s of Ca (34).
// Neo-Hookean: E_s is the "surface modulus of elasticity" of Ramanujan and Pozrikidis (1998),
// whose law is tau_1 = E_s/(3 l1 l2)(l1^2 - 1/(l1 l2)^2), so G_s = E_s/3 -- the same as the
// text's own SLS (63), g_0 = E_s/3 -- and the text validates against their D(Ca) at equal Ca
// (Fig. 7). (56) and (58)-(59) as printed have G_s = E_s; with that reading a sphere at
// Ca = 0.05 deforms to D = 0.12 at a = 5 where Ramanujan and Pozrikidis have 0.26 (solver/membrane3d/README.md
// "Conventions", measured). Skalak: (60)-(61) as printed, G_s = E_s (Skalak et al., Yazdani and
// Bagchi).
double shear_modulus_3d(const Scene& scene, const Units& units);

// The 3D membrane's law of a 3D scene's law; std::invalid_argument for the 2D law hooke.
membrane3d::ElasticLaw elastic_law_3d(MembraneLaw law);
// The 2D membrane's law of a 2D scene's law; std::invalid_argument for a 3D law.
membrane2d::ElasticLaw elastic_law_2d(MembraneLaw law);

// The Maxwell element of a 3D membrane in lattice units: the standard linear solid (63)-(67)
// when eta > 0, or the power law in the membrane (power_law.model "membrane"; the scene refuses
// both at once). E_m = G G_s; tau_m = mu / E_m in steps, mu the element's surface viscosity: the
// Kelvin-Voigt limit mu_s (a third of it in the dissertation's reading of (63),
// docs/conventions.md "Membrane viscosity in 3D"), or the power law's (102) at gamma = k,
// K a mu_a. present is false (and both 0) without one.
struct MaxwellElement3d {
  bool present = false;
  bool power_law = false;
  double E_m = 0;
  double tau_m = 0;
};
MaxwellElement3d maxwell_element_3d(const Scene& scene, const Units& units);

// The stiffness of a 3D membrane's Maxwell element (the standard linear solid (63)-(67), eta > 0,
// or the power law in the membrane) that the fluid feels over one time step, over the fluid's
// viscosity: E_m (1 - exp(-1/tau_m)) tau_m / nu, E_m = G G_s and tau_m its relaxation time in
// steps (the power law: E_m / nu, its relaxation time grows where the membrane shears slowly).
// The explicit coupling blows up when it is large (docs/guide/model.md "Relaxation time");
// 0 without a Maxwell element.
double maxwell_stiffness_number(const Scene& scene, double tau);

// The largest maxwell_stiffness_number the relaxation-time rule allows with the scene's delta
// (ib::maxwell_stiffness_bound; docs/guide/model.md "Relaxation time").
double maxwell_stiffness_bound(const Scene& scene);

// The relaxation time the solver runs a scene with: the scene's tau, or when it is 0 the
// rule of docs/guide/model.md "Relaxation time" (stability of the explicit membrane coupling).
double choose_tau(const Scene& scene);

}  // namespace capsule
