#pragma once
// The scene's own choices, each an enum with its one name table (solver/common/name_table.hpp),
// and the defaults a scene of each physics version and dimension gets. The choices of one part
// are that part's: the IB delta (solver/ib/delta.hpp), the membrane update
// (solver/ib/membrane_update.hpp), the precision (solver/lbm/precision.hpp) and the collision
// (solver/lbm/relaxation.hpp). docs/guide/scenes.md says what each name means.
#include <vector>

#include "solver/common/name_table.hpp"
#include "solver/ib/delta.hpp"
#include "solver/lbm/precision.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/scene/version.hpp"

namespace capsule {

// The physics a scene runs: this solver's, or version 5's defaults and canonical text.
enum class PhysicsVersion { current, v5 };
inline constexpr NameTable<PhysicsVersion, 2> physics_version_names{
    {{PhysicsVersion::current, capsule::physics_version}, {PhysicsVersion::v5, "5"}}};
constexpr const auto& name_table(PhysicsVersion) { return physics_version_names; }

// The unstressed shape: 2D circle | biconcave (24)-(25); 3D sphere | biconcave.
enum class Shape { circle, sphere, biconcave };
inline constexpr NameTable<Shape, 3> shape_names{
    {{Shape::circle, "circle"}, {Shape::sphere, "sphere"}, {Shape::biconcave, "biconcave"}}};
constexpr const auto& name_table(Shape) { return shape_names; }

// The membrane's elastic law: 2D Hooke (Sec. 2.5.1); 3D neo-Hookean (56) | Skalak (57).
enum class MembraneLaw { hooke, neo_hookean, skalak };
inline constexpr NameTable<MembraneLaw, 3> membrane_law_names{
    {{MembraneLaw::hooke, "hooke"}, {MembraneLaw::neo_hookean, "neo-hookean"}, {MembraneLaw::skalak, "skalak"}}};
constexpr const auto& name_table(MembraneLaw) { return membrane_law_names; }

// The reference shape of a 3D biconcave capsule (Table 1): none, or case A, B or C.
enum class ReferenceCase { none, A, B, C };
inline constexpr NameTable<ReferenceCase, 4> reference_case_names{
    {{ReferenceCase::none, "none"}, {ReferenceCase::A, "A"}, {ReferenceCase::B, "B"}, {ReferenceCase::C, "C"}}};
constexpr const auto& name_table(ReferenceCase) { return reference_case_names; }

// Where the power-law viscosity (102) acts (3D): the text's fluid shell (103)-(104), or the
// membrane's own viscous element.
enum class PowerLawModel { fluid_shell, membrane };
inline constexpr NameTable<PowerLawModel, 2> power_law_model_names{
    {{PowerLawModel::fluid_shell, "fluid_shell"}, {PowerLawModel::membrane, "membrane"}}};
constexpr const auto& name_table(PowerLawModel) { return power_law_model_names; }

// conventions.sls_viscosity (3D): the physical Kelvin-Voigt limit, or (63) read literally.
enum class SlsViscosity { physical, dissertation };
inline constexpr NameTable<SlsViscosity, 2> sls_viscosity_names{
    {{SlsViscosity::physical, "physical"}, {SlsViscosity::dissertation, "dissertation"}}};
constexpr const auto& name_table(SlsViscosity) { return sls_viscosity_names; }

// conventions.E_b_2d (2D): E_B = E_b a^2 E_s, or the text's (35) in its 2D units (twice that).
enum class BendingConvention2d { dimensionless, dissertation };
inline constexpr NameTable<BendingConvention2d, 2> bending_convention_2d_names{
    {{BendingConvention2d::dimensionless, "dimensionless"}, {BendingConvention2d::dissertation, "dissertation"}}};
constexpr const auto& name_table(BendingConvention2d) { return bending_convention_2d_names; }

// conventions.biconcave_2d (2D biconcave): (24)-(25) scaled to the circle's area, or as printed.
enum class BiconcaveSize2d { equivalent, dissertation };
inline constexpr NameTable<BiconcaveSize2d, 2> biconcave_size_2d_names{
    {{BiconcaveSize2d::equivalent, "equivalent"}, {BiconcaveSize2d::dissertation, "dissertation"}}};
constexpr const auto& name_table(BiconcaveSize2d) { return biconcave_size_2d_names; }

// resolution.kelvin_voigt_step (2D): how the implicit Kelvin-Voigt step (31) predicts velocities.
enum class KelvinVoigtStep { approximate_mobility, exact_mobility };
inline constexpr NameTable<KelvinVoigtStep, 2> kelvin_voigt_step_names{
    {{KelvinVoigtStep::approximate_mobility, "approximate_mobility"}, {KelvinVoigtStep::exact_mobility, "exact_mobility"}}};
constexpr const auto& name_table(KelvinVoigtStep) { return kelvin_voigt_step_names; }

// resolution.marker_inset as a rule: none given (a number, or 0), or the stresslet's
// (solver/ib/hydrodynamic_radius.hpp). "given" is the member file's word, not a scene value.
enum class MarkerInsetRule { given, stresslet };
inline constexpr NameTable<MarkerInsetRule, 2> marker_inset_rule_names{
    {{MarkerInsetRule::given, "given"}, {MarkerInsetRule::stresslet, "stresslet"}}};
constexpr const auto& name_table(MarkerInsetRule) { return marker_inset_rule_names; }

// output.snapshots: none, or VTK files of the 3D membrane.
enum class Snapshots { none, vtk };
inline constexpr NameTable<Snapshots, 2> snapshots_names{{{Snapshots::none, "none"}, {Snapshots::vtk, "vtk"}}};
constexpr const auto& name_table(Snapshots) { return snapshots_names; }

// How a protocol phase ends (PhaseSpec): shear until time | steady | theta | beta; recover
// until time | settled.
enum class StopCondition { time, steady, theta, beta, settled };
inline constexpr NameTable<StopCondition, 5> stop_condition_names{{{StopCondition::time, "time"},
                                                                   {StopCondition::steady, "steady"},
                                                                   {StopCondition::theta, "theta"},
                                                                   {StopCondition::beta, "beta"},
                                                                   {StopCondition::settled, "settled"}}};
constexpr const auto& name_table(StopCondition) { return stop_condition_names; }

// The defaults that depend on the physics version and the dimension (physics version 6:
// docs/findings/immersed_boundary_error_budget.md, accuracy_and_stability.md, kelvin_voigt_2d.md).
struct SceneDefaults {
  ib::Delta delta;
  lbm::CollisionModel collision;
  lbm::Precision precision;
  PowerLawModel power_law_model;
  KelvinVoigtStep kelvin_voigt_step;
  MarkerInsetRule marker_inset_rule;  // before a delta without a measured inset turns it off
  std::vector<double> domain;         // in units of a
  double a = 10;                      // the capsule's radius in lattice units
};

inline SceneDefaults scene_defaults(PhysicsVersion version, int dim) {
  const bool v6 = version == PhysicsVersion::current;
  SceneDefaults d;
  d.delta = dim == 3 && v6 ? ib::Delta::roma3 : ib::Delta::peskin4;
  d.collision = dim == 3 && v6 ? lbm::CollisionModel::trt : lbm::CollisionModel::mrt;
  // 3D single after the precision comparison (docs/findings/performance.md); 2D double.
  d.precision = dim == 3 ? lbm::Precision::single_precision : lbm::Precision::double_precision;
  d.power_law_model = v6 ? PowerLawModel::membrane : PowerLawModel::fluid_shell;
  d.kelvin_voigt_step = dim == 2 && v6 ? KelvinVoigtStep::exact_mobility : KelvinVoigtStep::approximate_mobility;
  d.marker_inset_rule = dim == 3 && v6 ? MarkerInsetRule::stresslet : MarkerInsetRule::given;
  d.domain = dim == 2 ? std::vector<double>{16, 12} : std::vector<double>{10, 10, 8};
  return d;
}

}  // namespace capsule
