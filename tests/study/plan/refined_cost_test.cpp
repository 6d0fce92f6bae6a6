// The planner's estimate of a refined member (resolution.refine): its node updates are half the
// coarse lattice's cells plus the fine lattice's per fine step, at the refined fluid's own
// measured rate, and its memory is the two levels' arrays, not the uniform lattice's at a.
#include <catch2/catch.hpp>

#include <cmath>

#include "solver/scene/memory_estimate.hpp"
#include "solver/scene/refined_block_extent.hpp"
#include "solver/scene/scene.hpp"
#include "study/plan/cost_estimate.hpp"

using namespace capsule;
using namespace capsule::study;

namespace {

nlohmann::json sphere(double a, bool refine) {
  nlohmann::json j = {{"dim", 3}, {"shape", "sphere"}, {"law", "neo-hookean"}, {"Ca", 0.2}, {"V", 1}, {"eta", 0}, {"E_b", 0.0},
                      {"resolution", {{"a", a}, {"mesh_level", 4}, {"precision", "double"}}},
                      {"protocol", {{"shear", {{"until", "time"}, {"kt", 6.5}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}}};
  if (refine) j["resolution"]["refine"] = {{"margin", 0.9}};
  return Scene::from_json(j, "s.json").to_json();
}

}  // namespace

TEST_CASE("a refined member's plan counts both levels' cells at the refined fluid's rate", "[plan][refine]") {
  const CostEstimate uniform = estimate_cost(sphere(20, false)), refined = estimate_cost(sphere(20, true));
  const RefinedCellCounts cells = refined_cell_counts(Scene::from_json(sphere(20, true), "s.json"));
  // a = 20: the coarse lattice 100 x 100 x 80; the cube 0.9 a beyond the markers' sphere
  // (r_m = 19.6) is 38 coarse cells a side, the fine lattice 2 (38 + 2) = 80 a side.
  CHECK(cells.coarse == 800000.0);
  CHECK(cells.fine == 80.0 * 80.0 * 80.0);
  CHECK(refined.nodes == std::llround(0.5 * cells.coarse + cells.fine));
  CHECK(uniform.nodes == 6400000);
  CHECK(refined.steps_per_kt == uniform.steps_per_kt);  // the fine lattice's steps
  // The refined fluid runs at its measured 28.5e6 node updates a second on one thread at this
  // size in double, 37.8e6 in single (docs/findings/refinement.md "Speed"), the uniform double
  // kernel at 55e6 (cost_estimate.cpp).
  CHECK(refined.fluid_seconds_per_step == Approx(refined.nodes / 28.5e6).epsilon(1e-3));
  nlohmann::json single = sphere(20, true);
  single["resolution"]["precision"] = "single";
  CHECK(estimate_cost(single).fluid_seconds_per_step == Approx(refined.nodes / 37.8e6).epsilon(1e-3));
  CHECK(refined.memory_bytes < 0.4 * uniform.memory_bytes);
  const MemoryEstimate m = estimate_memory(Scene::from_json(sphere(20, true), "s.json"));
  // Measured peak RSS of the a = 20 member at margin 0.7 (the fine lattice 72^3): 475 MB; at
  // margin 0.9 the fine lattice is 1.37 times larger. Without the restart copy:
  CHECK(m.total() - m.restart > 400e6);
  CHECK(m.total() - m.restart < 600e6);
}
