#pragma once
// A 3D cell given in physical (SI-based) units and its dimensionless groups (34)-(36): the
// conversion a scene's `physical` block goes through once (docs/guide/physical_units.md).
#include <string>
#include <vector>

#include "solver/scene/choices.hpp"

namespace capsule {

// The scene's `physical` block, in the units its key names say. A bending modulus is given in
// joules or in k_B T (with the temperature); the cytoplasm's viscosity defaults to the plasma's
// (V = 1), the membrane's to 0 (eta = 0), the density to water's, 1000 kg/m^3.
struct PhysicalCell {
  double radius_um = 0;                      // a, the cell's (equivalent) radius
  double shear_modulus_uN_per_m = 0;         // G_s, the small-deformation shear modulus
  double bending_modulus_J = 0;              // E_B of the Helfrich energy (71)
  double bending_modulus_kT = 0;             // E_B / (k_B T), when given instead of joules
  double temperature_K = 0;                  // needed with bending_modulus_kT
  double plasma_viscosity_mPa_s = 0;         // mu_a
  double cytoplasm_viscosity_mPa_s = 0;      // mu_c
  double membrane_viscosity_uN_s_per_m = 0;  // mu_s, the surface viscosity
  double shear_rate_per_s = 0;               // k
  double density_kg_per_m3 = 1000;           // rho, for the physical Reynolds number only

  // The bending modulus in joules, from whichever of the two keys the scene gave.
  double bending_modulus_in_J() const;
};

// The groups a PhysicalCell gives for a membrane law and a membrane-viscosity convention.
// E_s is the law's modulus in Ca (34) (neo-Hookean: 3 G_s, Ramanujan and Pozrikidis' surface
// modulus; Skalak: G_s); eta reads (36) in the scene's convention (sls_viscosity "physical":
// mu_s = eta a mu_a; "dissertation": mu_s = eta a mu_a / 3).
struct PhysicalGroups {
  double E_s = 0;          // N/m
  double Ca = 0;           // mu_a k a / E_s (34)
  double E_b = 0;          // E_B / (a^2 E_s) (35), dimensionless form
  double V = 0;            // mu_c / mu_a
  double eta = 0;          // mu_s / (a mu_a) (36)
  double Re = 0;           // rho k a^2 / mu_a, the cell's own Reynolds number
  double time_unit_s = 0;  // 1 / k
  double length_unit_um = 0;  // a
};
PhysicalGroups physical_groups(const PhysicalCell& cell, MembraneLaw law, SlsViscosity convention);

// The Reynolds number the lattice runs a physical scene at: the cell's own when it is above
// `floor_Re`, else floor_Re (a cell at physiological shear rates has Re ~ 1e-6, which the
// lattice cannot reach in useful time; any Re well below 1 is the same Stokes flow up to
// O(Re), docs/guide/physical_units.md "Reynolds number").
double lattice_Re(const PhysicalGroups& groups, double floor_Re);

// One line per quantity of the conversion, for `capsule units` (physical -> group, with
// formulas) and for the lattice: dx in micrometres and dt in seconds.
std::vector<std::string> conversion_lines(const PhysicalCell& cell, const PhysicalGroups& groups,
                                          MembraneLaw law, SlsViscosity convention);

}  // namespace capsule
