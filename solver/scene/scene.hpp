#pragma once
// One scene = one member of a study (docs/guide/scenes.md): the capsule, the fluid, the
// resolution, the protocol (shear, then recover) and what to write.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solver/scene/choices.hpp"
#include "solver/scene/numerics_preset.hpp"
#include "solver/scene/physical_cell.hpp"
#include "solver/scene/scene_conventions.hpp"
#include "solver/scene/scene_output.hpp"
#include "solver/scene/scene_power_law.hpp"
#include "solver/scene/scene_protocol.hpp"
#include "solver/scene/scene_resolution.hpp"
#include "solver/scene/version.hpp"

namespace capsule {

// A refused scene. what() reads "<file>: <json path>: <problem> (allowed: <range>)".
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The in-class defaults are those of a 2D scene of this solver's physics (scene_defaults).
// Nested like its JSON: the capsule's keys at the top level, then one member per section.
struct Scene {
  using PowerLaw = ScenePowerLaw;
  using Conventions = SceneConventions;
  using Resolution = SceneResolution;
  using Protocol = SceneProtocol;
  using Output = SceneOutput;

  int dim = 2;
  // The physics the scene runs (solver/scene/version.hpp): this solver's, or version 5, whose
  // defaults (scene_defaults) and canonical text keep a campaign run before version 6 as it was.
  PhysicsVersion physics_version = PhysicsVersion::current;
  // "dissertation": the defaults of the text's numerics (solver/scene/numerics_preset.hpp).
  Numerics numerics = Numerics::toolkit;
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
  PowerLaw power_law;
  Conventions conventions;
  Resolution resolution;
  Protocol protocol;
  Output output;

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
