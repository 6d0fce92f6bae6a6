// Same thread count -> bitwise identical fields. The kernel has no reductions and a
// static schedule, so the result does not even depend on the thread count; both are checked.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#include "solver/lbm/fluid.hpp"

using namespace capsule::lbm;

namespace {

// All populations and macroscopic fields after a stirred run with a viscosity field.
template <class L>
std::vector<double> run(int threads, int nx, int ny, int nz, Precision prec) {
  omp_set_num_threads(threads);
  Fluid<L> fluid(nx, ny, nz, 0.1, prec);
  fluid.initialise_velocity([](double x, double y, double z) {
    return std::array<double, 3>{0.02 * std::sin(0.3 * x + 0.1 * z), 0.01 * std::cos(0.2 * y * x), 0.01 * std::sin(z)};
  });
  for (std::size_t n = 0; n < fluid.size(); n += 7) fluid.set_viscosity(n, 0.05 + 0.001 * double(n % 13));
  fluid.set_wall_velocity(-0.03, 0.04);
  for (int s = 0; s < 30; ++s) {
    fluid.clear_force();
    for (int d = 0; d < L::D; ++d)
      for (std::size_t n = 0; n < fluid.size(); n += 5) fluid.force(d)[n] = 1e-5 * std::sin(double(n + s + d));
    fluid.step();
  }
  std::vector<double> out;
  for (int i = 0; i < L::Q; ++i)
    for (std::size_t n = 0; n < fluid.size(); ++n) out.push_back(fluid.population(i, n));
  for (int d = 0; d < 3; ++d) out.insert(out.end(), fluid.velocity(d), fluid.velocity(d) + fluid.size());
  out.insert(out.end(), fluid.density(), fluid.density() + fluid.size());
  return out;
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

template <class L>
void check(int nx, int ny, int nz, Precision prec) {
  const int saved = omp_get_max_threads();
  const int threads = std::max(2, saved);
  // Grids above the parallel threshold (4096 nodes), so the threads really split the work.
  const auto a = run<L>(threads, nx, ny, nz, prec);
  const auto b = run<L>(threads, nx, ny, nz, prec);
  const auto c = run<L>(1, nx, ny, nz, prec);
  omp_set_num_threads(saved);
  CHECK(bitwise_equal(a, b));
  CHECK(bitwise_equal(a, c));
}

}  // namespace

TEST_CASE("Same thread count gives bitwise identical fields", "[lbm]") {
  // Both precisions. The FMA clones (shifted_stream_collide.hpp) make the numbers depend on
  // the CPU's clone, never on the run or the thread count.
  for (Precision p : {Precision::double_precision, Precision::single_precision}) {
    check<D2Q9>(80, 64, 1, p);
    check<D3Q19>(20, 18, 16, p);
  }
}
