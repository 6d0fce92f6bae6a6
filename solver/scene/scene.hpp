#pragma once
// One scene = one member of a study (docs/guide/scenes.md): the capsule, the fluid, the
// resolution, the protocol (shear, then recover) and what to write.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solver/ib/membrane_update.hpp"
#include "solver/scene/choices.hpp"
#include "solver/scene/physical_cell.hpp"
#include "solver/scene/stretch_load.hpp"
#include "solver/scene/version.hpp"

namespace capsule {

// A refused scene. what() reads "<file>: <json path>: <problem> (allowed: <range>)".
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One phase of the protocol. Shear: until time (kt), steady (D_xy range over the last
// window_kt below tolerance), theta (inclination reaches value, rad, from above: tumbling,
// Sec. 4.1.2), beta (phase angle of the tracked element reaches value: tank-treading,
// Sec. 4.1.1), counted from after_kt on. Recover: until time (kt) or settled (as steady).
// max_kt caps the phase.
struct PhaseSpec {
  StopCondition until = StopCondition::time;
  double kt = 0;            // duration for until time
  double value = 0;         // threshold for theta / beta
  double tolerance = 1e-3;  // absolute range of D_xy over window_kt for "steady" / "settled"
  double window_kt = 2.0;
  double max_kt = 50.0;
  // recover only, settled: the window is max(window_kt, window_fraction x the time since the
  // stop), so a slow, non-monotone recovery is not taken as settled at a turning point.
  double window_fraction = 0.5;
  double oscillatory_period_kt = 0;  // shear only: > 0 -> wall speed (H/2) k sin(pi t / T) (Sec. 5.2.2)
  // shear only, theta / beta: a crossing counts from this kt on, so the stop falls in the
  // steady tumbling or tank-treading the text stops in (Sec. 4.1), not in the start-up.
  double after_kt = 0;
};

// The in-class defaults are those of a 2D scene of this solver's physics (scene_defaults).
struct Scene {
  int dim = 2;
  Shape shape = Shape::circle;           // 2D: circle | biconcave; 3D: sphere | biconcave
  MembraneLaw law = MembraneLaw::hooke;  // 2D: hooke; 3D: neo-hookean | skalak
  double C = 15;               // Skalak area-dilation constant (60)-(61)
  double Re = 0.05;            // Re = k a^2 / nu
  double Ca = 0;               // (34)
  double E_b = 0;              // (35)
  double V = 1;                // mu_c / mu_a
  double eta = 0;              // (36)
  double G = 50;               // E_m / E_s, standard linear solid (63)-(67)
  double c0 = 0;               // spontaneous curvature, units of 1/a
  ReferenceCase reference_case = ReferenceCase::none;  // 3D: none | A | B | C (Table 1)
  double volume_penalty = 0;   // K_v of (84), in units of E_s / a; 0 = off
  // 3D: the cell in physical units, when the scene gave it so; Ca, E_b, V, eta and Re are then
  // its groups (solver/scene/physical_cell.hpp), and times read in seconds as kt / k.
  std::optional<PhysicalCell> physical;
  double power_law_K = 0;      // (102), dimensionless (gamma in units of k); 0 = off
  double power_law_n = 1;
  // Where the power-law viscosity acts (3D): fluid_shell: the text's (103)-(104), spread over
  // the delta's four lattice spacings and added to the fluid viscosity there (its shell is
  // four lattice spacings thick whatever a, so it moves with the lattice); membrane: a
  // surface viscosity in the membrane mechanics, the standard linear solid's Maxwell element
  // with mu_s(gamma) per triangle (solver/membrane3d/elasticity.hpp), resolution-independent.
  PowerLawModel power_law_model = scene_defaults(PhysicsVersion::current, 2).power_law_model;
  // Readings of the dissertation that differ from the physical definitions (docs/conventions.md
  // "Conventions"); the physical ones are the default, the text's are there so its tables
  // can be regenerated and the difference explained.
  //  sls_viscosity (3D): "physical": the Kelvin-Voigt limit of the standard linear solid has
  //    surface viscosity mu_s = eta a mu_a; "dissertation": (63) read literally, the Maxwell
  //    element's shear modulus is g_1(0)/2 = E_m/3 with tau_m = mu_s/E_m, so the limit has mu_s/3.
  //  E_b_2d (2D): "dimensionless": E_B = E_b a^2 E_s; "dissertation": (35) E_B = E_b a E_s in
  //    the text's 2D units (a = 0.5, h = 0.05), i.e. E_B = 2 E_b a^2 E_s.
  //  biconcave_2d (2D biconcave): "equivalent": (24)-(25) scaled to enclose the area of the
  //    circle of radius a, as the text defines the equivalent radius (Sec. 2.1);
  //    "dissertation": (24)-(25) drawn with the printed a, which encloses the area of a circle
  //    of radius 0.740 a (the "characteristic length 1.48a" of Sec. 2.4 is its diameter).
  //    Ca, E_b, Re and the lattice keep the printed a in both.
  SlsViscosity sls_viscosity = SlsViscosity::physical;
  BendingConvention2d E_b_2d = BendingConvention2d::dimensionless;
  BiconcaveSize2d biconcave_2d = BiconcaveSize2d::equivalent;
  // The physics the scene runs (solver/scene/version.hpp): this solver's, or version 5, whose
  // defaults (scene_defaults) and canonical text keep a campaign run before version 6 as it was.
  PhysicsVersion physics_version = PhysicsVersion::current;
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
  PhaseSpec shear;
  PhaseSpec recover;
  // 3D: the optical-tweezers protocol (protocol.stretch, solver/scene/stretch_scene.hpp) in place
  // of the shear: walls at rest, the patches pulled until `shear`'s rule (time, or steady D_axial).
  std::optional<StretchLoad> stretch;
  double output_interval_kt = 0.05;
  std::vector<double> shapes_at_kt;
  Snapshots snapshots = Snapshots::none;

  // Parses and validates; throws SceneError naming source_name, the key and the allowed range.
  static Scene from_json(const nlohmann::json& j, const std::string& source_name);
  static Scene load(const std::string& path);
  // The complete canonical scene: every key, defaults filled, numbers typed by the schema
  // (marker_inset as its rule's name where a rule set it).
  nlohmann::json to_json() const;

  // The keys that canonical scenes of physics version 5 and older left out while they held
  // that version's default: dotted key -> the value an absent key means in such a scene of
  // that dim. Member files of older physics are read with it (analysis/report/scene_parameter.cpp).
  static const std::map<std::string, nlohmann::json>& omitted_defaults(int dim);


  // Lattice size (nx, ny, nz) from a and the domain (nz = 1 in 2D).
  std::vector<int> grid() const;
};

}  // namespace capsule
