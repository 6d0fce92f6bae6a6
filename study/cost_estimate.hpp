#pragma once
// A member's cost before it runs: lattice nodes x time steps, from its scene alone.
#include <nlohmann/json.hpp>

namespace capsule::study {

struct CostEstimate {
  long long nodes = 0;        // lattice nodes nx * ny * nz
  double kt_span = 0;         // shear + recovery time, kt; an upper bound when a phase ends on a condition (max_kt)
  bool kt_is_bound = false;   // true when kt_span is a max_kt cap rather than the set duration
  double steps_per_kt = 0;    // 1/k from Re, a and the tau the solver runs (choose_tau)
  double steps() const { return kt_span * steps_per_kt; }
  double node_steps() const { return static_cast<double>(nodes) * steps(); }
};

// From a complete canonical scene (Scene::to_json). Throws SceneError on an invalid scene.
CostEstimate estimate_cost(const nlohmann::json& canonical_scene);

}  // namespace capsule::study
