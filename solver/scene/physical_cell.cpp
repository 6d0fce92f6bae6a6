#include "solver/scene/physical_cell.hpp"

#include <cstdio>

#include "solver/membrane3d/constitutive_law.hpp"
#include "solver/scene/units.hpp"

namespace capsule {
namespace {

constexpr double boltzmann_J_per_K = 1.380649e-23;  // exact since the 2019 SI

std::string line(const char* format, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

}  // namespace

double PhysicalCell::bending_modulus_in_J() const {
  return bending_modulus_kT > 0 ? bending_modulus_kT * boltzmann_J_per_K * temperature_K : bending_modulus_J;
}

PhysicalGroups physical_groups(const PhysicalCell& c, MembraneLaw law, SlsViscosity convention) {
  const double a = c.radius_um * 1e-6;                  // m
  const double G_s = c.shear_modulus_uN_per_m * 1e-6;   // N/m
  const double mu_a = c.plasma_viscosity_mPa_s * 1e-3;  // Pa s
  const double mu_c = c.cytoplasm_viscosity_mPa_s * 1e-3;
  const double mu_s = c.membrane_viscosity_uN_s_per_m * 1e-6;  // N s/m
  const double k = c.shear_rate_per_s;
  PhysicalGroups g;
  g.E_s = G_s / membrane3d::law_modulus(elastic_law_3d(law), 1.0);  // the law's G_s = law_modulus(E_s)
  g.Ca = mu_a * k * a / g.E_s;                           // (34)
  g.E_b = c.bending_modulus_in_J() / (a * a * g.E_s);    // (35), E_B / (a^2 E_s)
  g.V = mu_c / mu_a;
  // (36): the Kelvin-Voigt limit of the membrane has mu_s = eta a mu_a in the physical reading,
  // a third of it in the dissertation's reading of (63) (docs/conventions.md).
  g.eta = mu_s / (a * mu_a) * (convention == SlsViscosity::dissertation ? 3.0 : 1.0);
  g.Re = c.density_kg_per_m3 * k * a * a / mu_a;
  g.time_unit_s = 1.0 / k;
  g.length_unit_um = c.radius_um;
  return g;
}

double lattice_Re(const PhysicalGroups& g, double floor_Re) { return g.Re > floor_Re ? g.Re : floor_Re; }

std::vector<std::string> conversion_lines(const PhysicalCell& c, const PhysicalGroups& g, MembraneLaw law,
                                          SlsViscosity convention) {
  std::vector<std::string> out;
  out.push_back(line("radius a                  %.6g um", c.radius_um));
  out.push_back(line("shear rate k              %.6g 1/s   time unit 1/k = %.6g s", c.shear_rate_per_s, g.time_unit_s));
  out.push_back(line("shear modulus G_s         %.6g uN/m  E_s of (34) = %.6g uN/m", c.shear_modulus_uN_per_m, g.E_s * 1e6) +
                (law == MembraneLaw::skalak ? " (Skalak: E_s = G_s)" : " (neo-Hookean: E_s = 3 G_s)"));
  out.push_back(line("bending modulus E_B       %.6g J", c.bending_modulus_in_J()) +
                (c.bending_modulus_kT > 0 ? line(" (%.6g k_B T at %.6g K)", c.bending_modulus_kT, c.temperature_K) : ""));
  out.push_back(line("plasma viscosity mu_a     %.6g mPa s", c.plasma_viscosity_mPa_s));
  out.push_back(line("cytoplasm viscosity mu_c  %.6g mPa s", c.cytoplasm_viscosity_mPa_s));
  out.push_back(line("membrane viscosity mu_s   %.6g uN s/m", c.membrane_viscosity_uN_s_per_m));
  out.push_back(line("density rho               %.6g kg/m^3", c.density_kg_per_m3));
  out.push_back(line("Ca  = mu_a k a / E_s      %.6g   (34)", g.Ca));
  out.push_back(line("E_b = E_B / (a^2 E_s)     %.6g   (35)", g.E_b));
  out.push_back(line("V   = mu_c / mu_a         %.6g", g.V));
  out.push_back(line("eta = mu_s / (a mu_a)     %.6g   (36)", g.eta) +
                (convention == SlsViscosity::dissertation ? ", times 3 in the dissertation's reading of (63)" : ""));
  out.push_back(line("Re  = rho k a^2 / mu_a    %.6g   (the cell's own)", g.Re));
  return out;
}

}  // namespace capsule
