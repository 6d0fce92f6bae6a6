#pragma once
// Small helpers shared by the lbm flow tests.
#include <cmath>
#include <vector>

#include "solver/lbm/fluid.hpp"

namespace capsule::lbm::test {

// Every fluid test runs in both precisions (scene resolution.precision).
inline constexpr Precision both_precisions[] = {Precision::double_precision, Precision::single_precision};
inline bool is_single(Precision p) { return p == Precision::single_precision; }

// u_x(y) along the column x = 0 (z = 0): flows in these tests are uniform in x and z.
template <class L>
std::vector<double> velocity_profile(const Fluid<L>& fluid, int d = 0) {
  std::vector<double> u(fluid.ny());
  for (int y = 0; y < fluid.ny(); ++y) u[y] = fluid.velocity(d)[fluid.index(0, y, 0)];
  return u;
}

// Largest deviation of any node from the column x = 0 (checks uniformity in x, z).
template <class L>
double non_uniformity(const Fluid<L>& fluid, int d = 0) {
  double worst = 0.0;
  for (int z = 0; z < fluid.nz(); ++z)
    for (int y = 0; y < fluid.ny(); ++y)
      for (int x = 0; x < fluid.nx(); ++x)
        worst = std::max(worst, std::abs(fluid.velocity(d)[fluid.index(x, y, z)] -
                                         fluid.velocity(d)[fluid.index(0, y, 0)]));
  return worst;
}

// Kinetic energy sum rho u^2 / 2 over the nodes (velocity(), density()).
template <class L>
double kinetic_energy(const Fluid<L>& fluid) {
  double e = 0.0;
  for (std::size_t n = 0; n < fluid.size(); ++n) {
    double u2 = 0.0;
    for (int d = 0; d < 3; ++d) u2 += fluid.velocity(d)[n] * fluid.velocity(d)[n];
    e += 0.5 * fluid.density()[n] * u2;
  }
  return e;
}

}  // namespace capsule::lbm::test
