#pragma once
// The scene's `conventions` section: readings of the dissertation that differ from the physical
// definitions (docs/conventions.md "Conventions"). The physical ones are the default; the text's
// are there so its tables can be regenerated and the difference explained.
#include "solver/scene/choices.hpp"

namespace capsule {

struct SceneConventions {
  // sls_viscosity (3D): "physical": the Kelvin-Voigt limit of the standard linear solid has
  // surface viscosity mu_s = eta a mu_a; "dissertation": (63) read literally, the Maxwell
  // element's shear modulus is g_1(0)/2 = E_m/3 with tau_m = mu_s/E_m, so the limit has mu_s/3.
  SlsViscosity sls_viscosity = SlsViscosity::physical;
  // E_b_2d (2D): "dimensionless": E_B = E_b a^2 E_s; "dissertation": (35) E_B = E_b a E_s in
  // the text's 2D units (a = 0.5, h = 0.05), i.e. E_B = 2 E_b a^2 E_s.
  BendingConvention2d E_b_2d = BendingConvention2d::dimensionless;
  // biconcave_2d (2D biconcave): "equivalent": (24)-(25) scaled to enclose the area of the
  // circle of radius a, as the text defines the equivalent radius (Sec. 2.1); "dissertation":
  // (24)-(25) drawn with the printed a, which encloses the area of a circle of radius 0.740 a
  // (the "characteristic length 1.48a" of Sec. 2.4 is its diameter). Ca, E_b, Re and the
  // lattice keep the printed a in both.
  BiconcaveSize2d biconcave_2d = BiconcaveSize2d::equivalent;
};

}  // namespace capsule
