#pragma once
// A member's cost before it runs (docs/guide/running.md "Time and memory estimates"): lattice nodes, time
// steps, and wall seconds on this kind of machine from a cost model calibrated by measurement:
//   seconds = steps x (fluid nodes / fluid rate / fluid speed-up + membrane cost per step / membrane speed-up)
// (the speed-ups with the thread count: 0.8 of a core per further thread for the fluid, 0.4
// for the 3D membrane side, none for the 2D membrane)
// with the fluid rate in lattice updates per second for the lattice (D2Q9 in or out of cache,
// D3Q19), the membrane cost per vertex (3D) or segment (2D) and term (elasticity, SLS, bending
// curvature fit, IB coupling by kernel width, viscosity contrast, power law), and the number
// of steps from the protocol: a set duration exactly, a phase that ends on a condition at its
// expected time (the length its nearest finished neighbours ran, phase_lengths.hpp; with none,
// steady shear: window + 1.6 kt, settled recovery: window + 2.6 kt, the measured ends of the
// default members), a theta or beta stop at its cap.
// After members have run, calibrate() corrects the model by their measured speed.
#include <nlohmann/json.hpp>
#include <vector>

#include "study/plan/phase_lengths.hpp"

namespace capsule::study {

struct CostEstimate {
  long long nodes = 0;        // lattice nodes nx * ny * nz
  double kt_span = 0;         // shear + recovery time, kt; an upper bound when a phase ends on a condition (max_kt)
  bool kt_is_bound = false;   // true when kt_span is a max_kt cap rather than the set duration
  double expected_kt = 0;     // the expected length (equal to kt_span for set durations)
  double steps_per_kt = 0;    // 1/k from Re, a and the tau the solver runs (choose_tau)
  double fluid_seconds_per_step = 0;     // one thread
  double membrane_seconds_per_step = 0;  // membrane forces, IB coupling, viscosity fields (one thread)
  double membrane_thread_efficiency = 0; // what each further thread adds to the membrane side (0: serial)
  double memory_bytes = 0;    // the solver's estimate (solver/scene/memory_estimate.hpp)
  double steps() const { return kt_span * steps_per_kt; }
  double expected_steps() const { return expected_kt * steps_per_kt; }
  double node_steps() const { return static_cast<double>(nodes) * steps(); }
  // Model seconds for a number of steps with this many OpenMP threads.
  double seconds_for_steps(double steps, int threads) const;
  double expected_seconds(int threads) const { return seconds_for_steps(expected_steps(), threads); }
};

// From a complete canonical scene (Scene::to_json). Throws SceneError on an invalid scene.
// With lengths, a phase that ends on a condition is expected to run as long as its nearest
// finished neighbours did (phase_lengths.hpp); without, or with none, at the default end.
CostEstimate estimate_cost(const nlohmann::json& canonical_scene, const PhaseLengths* lengths = nullptr);

// Measured speed of finished members against the model: factor = sum of measured wall
// seconds / sum of model seconds for the steps they took (1 with no measurement). And, for
// members whose phases end on a condition, how long those phases really ran: length_factor =
// sum of their steps / sum of the model's expected steps (the model's "window + 1.6 kt" is
// the default members' end; a campaign whose recoveries run to their caps is several times
// longer, and its members that ran say by how much).
struct SpeedCalibration {
  double factor = 1.0;
  int members = 0;
  double length_factor = 1.0;
  int length_members = 0;
  void add(const CostEstimate& c, double steps, int threads, double wall_seconds);
  // A member's expected steps, those of a phase that ends on a condition corrected by
  // length_factor, never beyond its caps.
  double expected_steps(const CostEstimate& c) const;
  // Seconds for a member that has not run: its expected steps at the model's speed corrected by factor.
  double seconds(const CostEstimate& c, int threads) const;

 private:
  double measured_ = 0, model_ = 0;
  double measured_steps_ = 0, expected_steps_ = 0;
};

}  // namespace capsule::study
