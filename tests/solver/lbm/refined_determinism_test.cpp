// A refined run is bitwise reproducible: twice on the same thread count, and on 1 against 2
// OpenMP threads (every parallel loop writes its own cells; the sums run in a fixed order).
#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <vector>

#include "solver/lbm/refinement/refined_fluid.hpp"

using namespace capsule::lbm;
using namespace capsule::lbm::refinement;

namespace {

template <class L>
std::vector<double> run(int threads, int nx, int ny, int nz, const BlockExtent& block, int steps,
                        Precision precision = Precision::double_precision) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  RefinedFluid<L> fluid(nx, ny, nz, 0.08, block, precision);
  fluid.set_wall_velocity(-0.03, 0.05);
  fluid.initialise_velocity([&](double x, double y, double z) {
    return std::array<double, 3>{0.02 * std::sin(0.7 * y + 0.3 * z), 0.01 * std::cos(0.9 * x), 0.01 * std::sin(x)};
  });
  const auto& b = fluid.block();
  for (std::size_t n = 0; n < b.fine_size(); ++n) fluid.fine_force(1)[n] = 1e-5 * std::sin(0.3 * double(n));
  for (int s = 0; s < steps; ++s) fluid.step();
  omp_set_num_threads(saved);
  std::vector<double> state = fluid.coarse_populations();
  const std::vector<double> fine = fluid.fine_populations();
  state.insert(state.end(), fine.begin(), fine.end());
  return state;
}

}  // namespace

TEST_CASE("refined block: same result twice and on 1 and 2 threads", "[lbm][refinement]") {
  const BlockExtent box2{{3, 4, 0}, {9, 12, 1}};
  const auto a = run<D2Q9>(2, 12, 16, 1, box2, 300);
  CHECK(a == run<D2Q9>(2, 12, 16, 1, box2, 300));
  CHECK(a == run<D2Q9>(1, 12, 16, 1, box2, 300));
  const BlockExtent box3{{3, 3, 3}, {6, 7, 6}};
  CHECK(run<D3Q19>(1, 9, 10, 9, box3, 60) == run<D3Q19>(2, 9, 10, 9, box3, 60));
  // Float populations, double arithmetic: the same passes, so the same rule.
  const auto single = run<D3Q19>(1, 9, 10, 9, box3, 60, Precision::single_precision);
  CHECK(single == run<D3Q19>(2, 9, 10, 9, box3, 60, Precision::single_precision));
  CHECK(single != run<D3Q19>(1, 9, 10, 9, box3, 60));
}
