// In-place streaming (AA pattern, in_place_stream_collide.hpp, what Fluid runs by default)
// equals the two-lattice kernel (shifted_stream_collide.hpp) bitwise: same collision, same
// walls, after odd and even step counts (the two AA states), with moving walls, a force,
// per-node viscosities, macroscopic rows and several threads.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "solver/lbm/fluid.hpp"
#include "tests/solver/lbm/flow_helpers.hpp"

using namespace capsule::lbm;

namespace {

template <class L>
void compare(int nx, int ny, int nz, Precision prec, int steps) {
  Fluid<L> aa(nx, ny, nz, 0.1, prec, Streaming::in_place), two(nx, ny, nz, 0.1, prec, Streaming::two_lattice);
  for (Fluid<L>* f : {&aa, &two}) {
    f->initialise_velocity([](double x, double y, double z) {
      return std::array<double, 3>{0.02 * std::sin(0.3 * x + 0.1 * z), 0.01 * std::cos(0.2 * y * x), L::D == 3 ? 0.01 * std::sin(z) : 0.0};
    });
    for (std::size_t n = 0; n < f->size(); n += 3) f->set_viscosity(n, 0.05 + 0.01 * double(n % 11));
  }
  bool same_f = true, same_u = true;
  for (int s = 0; s < steps; ++s) {
    for (Fluid<L>* f : {&aa, &two}) {
      f->set_wall_velocity(-0.03 * std::cos(0.1 * s), 0.04);
      f->clear_force();
      for (int d = 0; d < L::D; ++d)
        for (std::size_t n = 0; n < f->size(); n += 5) f->force(d)[n] = 1e-5 * std::sin(double(n + s + d));
      if (s % 3 == 1) f->set_macroscopic_region({{1, ny / 2, 0, 1}});
      else f->set_macroscopic_everywhere();
      f->step();
    }
    for (int i = 0; i < L::Q; ++i)
      for (std::size_t n = 0; n < aa.size(); ++n) same_f = same_f && aa.population(i, n) == two.population(i, n);
    for (int d = 0; d < 3; ++d)
      for (std::size_t n = 0; n < aa.size(); ++n) same_u = same_u && aa.velocity(d)[n] == two.velocity(d)[n];
    for (std::size_t n = 0; n < aa.size(); ++n) same_u = same_u && aa.density()[n] == two.density()[n];
  }
  INFO(capsule::choice_name(prec) << " Q" << L::Q << " " << nx << "x" << ny << "x" << nz << " steps " << steps);
  CHECK(same_f);
  CHECK(same_u);
  CHECK(aa.total_mass() == Approx(two.total_mass()).epsilon(1e-15));
}

}  // namespace

TEST_CASE("In-place (AA) streaming equals the two-lattice kernel bitwise", "[lbm]") {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(std::max(2, saved));
  for (Precision p : test::both_precisions) {
    compare<D2Q9>(13, 7, 1, p, 7);
    compare<D2Q9>(80, 64, 1, p, 6);     // above the parallel threshold
    compare<D3Q19>(9, 6, 5, p, 5);
    compare<D3Q19>(20, 18, 16, p, 8);   // above the parallel threshold
    compare<D3Q19>(5, 1, 3, p, 4);      // one row between both walls
  }
  omp_set_num_threads(saved);
}
