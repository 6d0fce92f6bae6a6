#pragma once
// Small helpers shared by the refined-block tests (solver/lbm/refinement/).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "solver/lbm/refinement/refined_fluid.hpp"

namespace capsule::lbm::test {

// Largest |u_a - exact_a(x, y, z)| over the uncovered coarse cells and the block's fine cells
// (positions in coarse spacings).
template <class L>
double refined_velocity_error(const refinement::RefinedFluid<L>& fluid,
                              const std::function<std::array<double, 3>(double, double, double)>& exact) {
  const auto& b = fluid.block();
  double worst = 0.0;
  for (int z = 0; z < b.coarse_n(2); ++z)
    for (int y = 0; y < b.coarse_n(1); ++y)
      for (int x = 0; x < b.coarse_n(0); ++x) {
        if (b.covered({x, y, z})) continue;
        const auto u = exact(x + 0.5, y + 0.5, z + 0.5);
        for (int a = 0; a < L::D; ++a)
          worst = std::max(worst, std::abs(fluid.coarse_velocity(a)[b.coarse_index(x, y, z)] - u[a]));
      }
  for (int z = 0; z < b.fine_n(2); ++z)
    for (int y = 0; y < b.fine_n(1); ++y)
      for (int x = 0; x < b.fine_n(0); ++x) {
        if (!b.fine_in_block({x, y, z})) continue;
        const auto p = b.fine_centre({x, y, z});
        const auto u = exact(p[0], p[1], p[2]);
        for (int a = 0; a < L::D; ++a)
          worst = std::max(worst, std::abs(fluid.fine_velocity(a)[b.fine_index(x, y, z)] - u[a]));
      }
  return worst;
}

}  // namespace capsule::lbm::test
