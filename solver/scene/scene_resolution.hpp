#pragma once
// The scene's `resolution` section (docs/guide/scenes.md "Keys"): the lattice, the membrane's
// discretisation and the numerical choices of the fluid, the immersed boundary and the membrane.
#include <optional>
#include <vector>

#include "solver/ib/delta.hpp"
#include "solver/ib/membrane_update.hpp"
#include "solver/lbm/precision.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/scene/choices.hpp"

namespace capsule {

// resolution.refine (3D): the fluid refined by a factor 2 in one static block about the capsule
// (docs/guide/refinement.md "In a scene"); the scene's a is then the fine lattice's radius.
struct SceneRefinement {
  int levels = 1;       // factor-2 levels; one is built
  double margin = 0.6;  // the block beyond the start shape's circumscribed sphere, in units of a
};

// The in-class defaults are those of a 2D scene of this solver's physics (scene_defaults).
struct SceneResolution {
  double a = 10;               // capsule (equivalent) radius in lattice nodes
  std::vector<double> domain = scene_defaults(PhysicsVersion::current, 2).domain;  // in units of a
  int segments = 140;          // 2D membrane segments
  int mesh_level = 4;          // 3D icosahedron subdivisions (4 -> 2562 vertices)
  double tau = 0;              // relaxation time; 0 = chosen by the solver
  // The IB delta (scene key resolution.kernel; solver/ib/delta.hpp).
  ib::Delta delta = scene_defaults(PhysicsVersion::current, 2).delta;
  // The fluid's populations (solver/lbm/precision.hpp).
  lbm::Precision precision = scene_defaults(PhysicsVersion::current, 2).precision;
  // 3D position update (20) (solver/ib/membrane_update.hpp).
  ib::MembraneUpdate membrane_update = ib::MembraneUpdate::euler;
  // 3D: the markers (and the reference shape) sit this many lattice units inside the radius a,
  // the moduli unchanged (simulation3d.cpp "Marker inset"), so that the smeared shell, whose
  // hydrodynamic radius is larger than its markers', acts as the radius a. marker_inset_rule
  // stresslet (the 3D default) computes it from a and the delta (solver/ib/hydrodynamic_radius.hpp);
  // given when the scene gave a number (0: markers on the radius a).
  double marker_inset = 0;
  MarkerInsetRule marker_inset_rule = scene_defaults(PhysicsVersion::current, 2).marker_inset_rule;
  // 2D implicit Kelvin-Voigt step (31) (solver/membrane2d/membrane.hpp): approximate_mobility
  // predicts the node velocities with the scalar self-mobility 2 (3/8)^2 and the last step's
  // velocity (stable up to eta ~ 20 at a = 10); exact_mobility solves with the immersed
  // boundary's real same-step mobility and force-free velocity (solver/ib/mobility.hpp).
  KelvinVoigtStep kelvin_voigt_step = scene_defaults(PhysicsVersion::current, 2).kelvin_voigt_step;
  // 3D relaxation rates of the fluid (solver/lbm/relaxation.hpp): mrt, the text's rates (the
  // odd moments' Lambda grows as (3 nu)^2 with a node's viscosity), or trt, two relaxation
  // times with the odd moments at Lambda = 3/16 at every node (a viscosity contrast then no
  // longer moves with tau: docs/findings/accuracy_and_stability.md). 2D: mrt only (a TRT already).
  lbm::CollisionModel collision = scene_defaults(PhysicsVersion::current, 2).collision;
  // A refined block about the capsule; absent: the uniform lattice (and a canonical scene
  // without the key, so the ids of unrefined members do not depend on it).
  std::optional<SceneRefinement> refine;
};

}  // namespace capsule
