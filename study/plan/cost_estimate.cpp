#include "study/plan/cost_estimate.hpp"
#include "solver/scene/refined_block_extent.hpp"

#include <algorithm>
#include <cmath>

#include "solver/scene/memory_estimate.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule::study {

namespace {

// 2D, one thread (docs/findings/performance.md "Time estimates against measured runs"): fitted
// to the 164 shipped 2D members' wall seconds per step (scripts/fit-cost-model, 2026-12-07),
// relative least squares with the 15 % worst left out (members that ran beside others): the
// fluid in cache at 338 MLUPS (the kernel rewrite doubled the 175 MLUPS `capsule bench lbm`
// gave before it); beyond the cache 96 MLUPS, the last bench figure, not re-measured (no
// shipped 2D member is that large). Membrane and coupling 0.18 us per segment and step.
constexpr double kD2Q9CachedRate = 338e6, kD2Q9Rate = 96e6;
constexpr double kD2Q9CacheNodes = 250e3;  // ~ 2 x 9 x 8 B x nodes within a few MB of cache
constexpr double k2DPerSegment = 0.18e-6;
// 3D (docs/findings/performance.md "The membrane side of a 3D step" and "Finer members",
// `capsule bench member3d`, one thread, 2026-12-04): the member's fluid (rho and u written only
// near the membrane) at 160 MLUPS in single precision and 83 MLUPS in double on the 800 000
// nodes of a = 10, and about 90 / 55 MLUPS on the 6 400 000 nodes of a = 20 (the machine's
// speed varied by 20-30 % between runs); log-linear in the node count between the two and
// constant beyond. Per vertex and step at a = 10, level 4
// (2562 vertices): IB coupling with Peskin's 4-point kernel 0.59 ms, elastic forces 0.21 ms,
// the curvature fit and bending 1.0 ms. Not re-measured since the kernel rewrite (from the
// member timings of 2026-11-25, scaled as then): the power law 1.4 ms, the SLS memory about
// half the elastic cost, the viscosity contrast's band (6^3 nodes per vertex) 3.0 ms.
constexpr double kD3Q19Nodes[2] = {0.8e6, 6.4e6}, kD3Q19SingleRate[2] = {160e6, 90e6}, kD3Q19DoubleRate[2] = {83e6, 55e6};
constexpr double k3DCouplingPerVertex = 0.23e-6, k3DElasticPerVertex = 0.085e-6, k3DSlsPerVertex = 0.04e-6,
                 k3DCurvaturePerVertex = 0.40e-6, k3DPowerLawPerVertex = 0.55e-6, k3DContrastPerVertex = 1.2e-6;
// The 2D viscosity contrast (a 6 x 6 box per node) 0.21 us per segment, the implicit
// Kelvin-Voigt tension (eta > 0) 1.31 us: the same fit.
constexpr double k2DContrastPerSegment = 0.21e-6, k2DKelvinVoigtPerSegment = 1.31e-6;
// Each further thread adds 0.8 of a core to the fluid (2 threads: 1.86x D2Q9, 1.79x D3Q19)
// and 0.4 of a core to the 3D membrane side (2 threads: 1.3-1.45x, bench member3d); the 2D
// membrane (140 segments) runs on one thread.
constexpr double kThreadEfficiency = 0.8, k3DMembraneThreadEfficiency = 0.4;
// The refined fluid (resolution.refine; docs/findings/refinement.md "Speed"): node updates of
// both levels per second on one thread, from the fluid seconds of a 3D sphere member (level
// 4, 1200 fine steps), idle machine, 2026-12-08, build d232b86: a = 10 with margin 0.6 (9.67e4
// updates per fine step) 35.0e6 in double, 50.4e6 in single; a = 20 with margin 0.9 (9.12e5)
// 28.5e6 and 37.8e6. Log-linear between, constant beyond.
constexpr double kRefinedNodes[2] = {9.67e4, 9.12e5}, kRefinedDoubleRate[2] = {35.0e6, 28.5e6},
                 kRefinedSingleRate[2] = {50.4e6, 37.8e6};
double refined_rate(double updates, bool single) {
  const double* rate = single ? kRefinedSingleRate : kRefinedDoubleRate;
  const double x = std::clamp(std::log(updates / kRefinedNodes[0]) / std::log(kRefinedNodes[1] / kRefinedNodes[0]), 0.0, 1.0);
  return rate[0] * std::pow(rate[1] / rate[0], x);
}

double d3q19_rate(double nodes, bool single) {
  const double* rate = single ? kD3Q19SingleRate : kD3Q19DoubleRate;
  const double x = std::clamp(std::log(nodes / kD3Q19Nodes[0]) / std::log(kD3Q19Nodes[1] / kD3Q19Nodes[0]), 0.0, 1.0);
  return rate[0] * std::pow(rate[1] / rate[0], x);
}

double expected_phase_kt(const PhaseSpec& p, bool recovery) {
  if (p.until == StopCondition::time) return p.kt;
  if (p.until == StopCondition::steady || p.until == StopCondition::settled)
    return std::min(p.max_kt, p.window_kt + (recovery ? 2.6 : 1.6));
  return p.max_kt;  // theta / beta stops: no prior; the cap
}

}  // namespace

double CostEstimate::seconds_for_steps(double steps, int threads) const {
  const double t = std::max(1, threads);
  return steps * (fluid_seconds_per_step / (1.0 + kThreadEfficiency * (t - 1.0)) +
                  membrane_seconds_per_step / (1.0 + membrane_thread_efficiency * (t - 1.0)));
}

CostEstimate estimate_cost(const nlohmann::json& canonical_scene, const PhaseLengths* lengths) {
  const Scene scene = Scene::from_json(canonical_scene, "member scene");
  CostEstimate c;
  c.nodes = 1;
  for (int n : scene.grid()) c.nodes *= n;
  const auto phase_span = [&c](const PhaseSpec& p) {
    if (p.until == StopCondition::time) return p.kt;
    c.kt_is_bound = true;
    return p.max_kt;
  };
  c.kt_span = phase_span(scene.protocol.shear) + phase_span(scene.protocol.recover);
  // A phase that ends on a condition: as long as its nearest finished neighbours ran, when
  // there are any (phase_lengths.hpp), else the default members' measured end.
  const auto expected = [&](const PhaseSpec& p, bool recovery) {
    if (lengths != nullptr)
      if (const auto kt = lengths->expected_kt(canonical_scene, recovery)) return *kt;
    return expected_phase_kt(p, recovery);
  };
  const bool no_recovery = scene.protocol.recover.until == StopCondition::time && scene.protocol.recover.kt <= 0;
  c.expected_kt = expected(scene.protocol.shear, false) + (no_recovery ? 0.0 : expected(scene.protocol.recover, true));
  c.steps_per_kt = units_for(scene, choose_tau(scene)).steps_per_kt;  // the tau the solver will run
  const double nodes = static_cast<double>(c.nodes);
  if (scene.dim == 2) {
    c.fluid_seconds_per_step = nodes / (nodes <= kD2Q9CacheNodes ? kD2Q9CachedRate : kD2Q9Rate);
    c.membrane_seconds_per_step = scene.resolution.segments * (k2DPerSegment + (scene.V != 1.0 ? k2DContrastPerSegment : 0.0) +
                                                    (scene.eta > 0 ? k2DKelvinVoigtPerSegment : 0.0));
  } else {
    c.fluid_seconds_per_step = nodes / d3q19_rate(nodes, scene.resolution.precision == lbm::Precision::single_precision);
    if (scene.resolution.refine) {
      // The refined fluid: per fine step half the coarse lattice's cells and all the fine
      // lattice's, at its own rate in its precision (refined_rate).
      const RefinedCellCounts cells = refined_cell_counts(scene);
      const double updates = 0.5 * cells.coarse + cells.fine;
      c.nodes = std::llround(updates);
      c.fluid_seconds_per_step = updates / refined_rate(updates, scene.resolution.precision == lbm::Precision::single_precision);
    }
    c.membrane_thread_efficiency = k3DMembraneThreadEfficiency;
    const double vertices = 10.0 * std::pow(4.0, scene.resolution.mesh_level) + 2.0;
    const double support = ib::delta_support_nodes(scene.resolution.delta, 3);
    double per_vertex = k3DCouplingPerVertex * support / 64.0 + k3DElasticPerVertex;
    const bool membrane_power_law = scene.power_law.K > 0 && scene.power_law.model == PowerLawModel::membrane;
    if (scene.eta > 0 || membrane_power_law) per_vertex += k3DSlsPerVertex;  // the power law's own SLS step (not measured apart)
    if (scene.E_b > 0 || scene.volume_penalty > 0) per_vertex += k3DCurvaturePerVertex;
    if (scene.power_law.K > 0 && !membrane_power_law) per_vertex += k3DPowerLawPerVertex;
    if (scene.V != 1.0) per_vertex += k3DContrastPerVertex;
    c.membrane_seconds_per_step = vertices * per_vertex;
  }
  c.memory_bytes = estimate_memory(scene).total();
  return c;
}

void SpeedCalibration::add(const CostEstimate& c, double steps, int threads, double wall_seconds) {
  const double model = c.seconds_for_steps(steps, threads);
  if (!(model > 0) || !(wall_seconds > 0)) return;
  // Running sums, kept as the factor: factor = sum(measured) / sum(model).
  measured_ += wall_seconds;
  model_ += model;
  ++members;
  factor = measured_ / model_;
  if (c.kt_is_bound && c.expected_steps() > 0 && steps > 0) {
    measured_steps_ += steps;
    expected_steps_ += c.expected_steps();
    ++length_members;
    length_factor = measured_steps_ / expected_steps_;
  }
}

double SpeedCalibration::expected_steps(const CostEstimate& c) const {
  return c.kt_is_bound ? std::min(c.steps(), c.expected_steps() * length_factor) : c.expected_steps();
}

double SpeedCalibration::seconds(const CostEstimate& c, int threads) const {
  return c.seconds_for_steps(expected_steps(c), threads) * factor;
}

}  // namespace capsule::study
