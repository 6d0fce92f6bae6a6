#include "study/plan/cost_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "solver/scene/memory_estimate.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule::study {

namespace {

// Calibration (one thread, the 2-core development machine, docs/findings/performance.md "The fluid kernel before the rewrite"):
// `capsule bench lbm`: D2Q9 175 MLUPS while the lattice fits in cache (160 x 120), 96 MLUPS
// beyond (2048 x 2048); D3Q19 27.5 MLUPS.
constexpr double kD2Q9CachedRate = 175e6, kD2Q9Rate = 96e6, kD3Q19Rate = 27.5e6;
constexpr double kD2Q9CacheNodes = 250e3;  // ~ 2 x 9 x 8 B x nodes within a few MB of cache
// 2D member at a = 10, 140 segments: membrane and coupling 1.9 s over 106 200 steps.
constexpr double k2DPerSegment = 0.128e-6;
// 3D, per vertex and step at a = 10, level 4 (2562 vertices): IB coupling with Peskin's
// 4-point kernel 3.0 ms, elastic forces 0.5 ms, the curvature fit and bending 3.5 ms, power
// law 1.4 ms; the SLS memory about half the elastic cost; the viscosity contrast's band
// (6^3 nodes per vertex) about as much as the coupling.
constexpr double k3DCouplingPerVertex = 1.17e-6, k3DElasticPerVertex = 0.20e-6, k3DSlsPerVertex = 0.10e-6,
                 k3DCurvaturePerVertex = 1.37e-6, k3DPowerLawPerVertex = 0.55e-6, k3DContrastPerVertex = 1.2e-6;
// The 2D viscosity contrast visits a 6 x 6 box per node: as much again as the membrane.
constexpr double k2DContrastPerSegment = 0.15e-6;
// Each further thread adds 0.8 of a core to the fluid (2 threads: 1.86x D2Q9, 1.79x D3Q19).
constexpr double kThreadEfficiency = 0.8;

double expected_phase_kt(const PhaseSpec& p, bool recovery) {
  if (p.until == "time") return p.kt;
  if (p.until == "steady" || p.until == "settled")
    return std::min(p.max_kt, p.window_kt + (recovery ? 2.6 : 1.6));
  return p.max_kt;  // theta / beta stops: no prior; the cap
}

}  // namespace

double CostEstimate::seconds_for_steps(double steps, int threads) const {
  const double t = std::max(1, threads);
  return steps * (fluid_seconds_per_step / (1.0 + kThreadEfficiency * (t - 1.0)) + membrane_seconds_per_step);
}

CostEstimate estimate_cost(const nlohmann::json& canonical_scene) {
  const Scene scene = Scene::from_json(canonical_scene, "member scene");
  CostEstimate c;
  c.nodes = 1;
  for (int n : scene.grid()) c.nodes *= n;
  const auto phase_span = [&c](const PhaseSpec& p) {
    if (p.until == "time") return p.kt;
    c.kt_is_bound = true;
    return p.max_kt;
  };
  c.kt_span = phase_span(scene.shear) + phase_span(scene.recover);
  c.expected_kt = expected_phase_kt(scene.shear, false) + expected_phase_kt(scene.recover, true);
  if (scene.recover.until == "time" && scene.recover.kt <= 0) c.expected_kt = expected_phase_kt(scene.shear, false);
  c.steps_per_kt = units_for(scene, choose_tau(scene)).steps_per_kt;  // the tau the solver will run
  const double nodes = static_cast<double>(c.nodes);
  if (scene.dim == 2) {
    c.fluid_seconds_per_step = nodes / (nodes <= kD2Q9CacheNodes ? kD2Q9CachedRate : kD2Q9Rate);
    c.membrane_seconds_per_step = scene.segments * (k2DPerSegment + (scene.V != 1.0 ? k2DContrastPerSegment : 0.0));
  } else {
    c.fluid_seconds_per_step = nodes / kD3Q19Rate;
    const double vertices = 10.0 * std::pow(4.0, scene.mesh_level) + 2.0;
    const double support = scene.kernel == "linear2" ? 8.0 : scene.kernel == "roma3" ? 27.0 : 64.0;
    double per_vertex = k3DCouplingPerVertex * support / 64.0 + k3DElasticPerVertex;
    if (scene.eta > 0) per_vertex += k3DSlsPerVertex;
    if (scene.E_b > 0 || scene.volume_penalty > 0) per_vertex += k3DCurvaturePerVertex;
    if (scene.power_law_K > 0) per_vertex += k3DPowerLawPerVertex;
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

double SpeedCalibration::seconds(const CostEstimate& c, int threads) const {
  const double steps = c.kt_is_bound ? std::min(c.steps(), c.expected_steps() * length_factor) : c.expected_steps();
  return c.seconds_for_steps(steps, threads) * factor;
}

}  // namespace capsule::study
