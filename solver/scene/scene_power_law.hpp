#pragma once
// The scene's `power_law` section: the power-law membrane viscosity (102) and where it acts.
#include "solver/scene/choices.hpp"

namespace capsule {

struct ScenePowerLaw {
  double K = 0;  // (102), dimensionless (gamma in units of k); 0 = off
  double n = 1;
  // Where it acts (3D): fluid_shell: the text's (103)-(104), spread over the delta's four
  // lattice spacings and added to the fluid viscosity there (its shell is four lattice spacings
  // thick whatever a, so it moves with the lattice); membrane: a surface viscosity in the
  // membrane mechanics, the standard linear solid's Maxwell element with mu_s(gamma) per
  // triangle (solver/membrane3d/elasticity.hpp), resolution-independent.
  PowerLawModel model = scene_defaults(PhysicsVersion::current, 2).power_law_model;
};

}  // namespace capsule
