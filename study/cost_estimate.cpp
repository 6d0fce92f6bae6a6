#include "study/cost_estimate.hpp"

#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule::study {

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
  c.steps_per_kt = units_for(scene, choose_tau(scene)).steps_per_kt;  // the tau the solver will run
  return c;
}

}  // namespace capsule::study
