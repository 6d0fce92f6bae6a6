// Plane Couette flow between the moving walls (half-way bounce-back with the
// moving-wall correction): the exact linear profile u(y) = u_b + (u_t - u_b) y / H.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/lbm/fluid.hpp"
#include "tests/solver/lbm/flow_helpers.hpp"

using namespace capsule::lbm;

namespace {

// Runs from rest to steady state and returns max |u - exact| / max |exact|.
template <class L>
double couette_error(int nx, int ny, int nz, double nu, double u_bottom, double u_top, int steps, Precision p) {
  Fluid<L> fluid(nx, ny, nz, nu, p);
  fluid.set_wall_velocity(u_bottom, u_top);
  for (int s = 0; s < steps; ++s) fluid.step();
  const auto u = test::velocity_profile(fluid);
  double err = 0.0, scale = 0.0;
  for (int y = 0; y < ny; ++y) {
    const double exact = u_bottom + (u_top - u_bottom) * (y + 0.5) / ny;
    err = std::max(err, std::abs(u[y] - exact));
    scale = std::max(scale, std::abs(exact));
  }
  // The flow must be uniform in x and z to round-off (1e-15 of wall speeds 0.05; every node
  // of a row does the same operations on the same numbers, in either precision).
  REQUIRE(test::non_uniformity(fluid) < 1e-15);
  return err / scale;
}

}  // namespace

// Steps: the slowest transient decays like exp(-nu (pi/H)^2 t); with H = 8 and
// nu = 1/6 (tau = 1), 2500 steps give exp(-51) ~ 1e-22, far below the 1e-8 demanded.
// With nu = 0.05 (tau = 0.65), 8000 steps give exp(-62).
// The half-way bounce-back reproduces linear profiles exactly, so the 1e-8 bound
// (set by the issue) leaves only round-off and the decayed transient.
// Single precision: the populations carry ~7 digits of f_i - w_i (~0.01 here); the float
// round-off of every step (~6e-8 relative) accumulates over the diffusion time H^2/nu
// (~1300 steps at nu = 0.05) before it decays, so the profile is exact only to ~1e-6 of U
// (measured 1.6e-6 at nu = 0.05, 3e-7 at nu = 1/6): bound 1e-5.
TEST_CASE("Couette flow reaches the exact linear profile (D2Q9)", "[lbm]") {
  for (Precision p : test::both_precisions) {
    const double tol = test::is_single(p) ? 1e-5 : 1e-8;
    INFO("precision " << capsule::choice_name(p));
    CHECK(couette_error<D2Q9>(4, 8, 1, 1.0 / 6.0, -0.05, 0.05, 2500, p) < tol);
    CHECK(couette_error<D2Q9>(3, 8, 1, 0.05, 0.0, 0.04, 8000, p) < tol);
  }
}

TEST_CASE("Couette flow reaches the exact linear profile (D3Q19)", "[lbm]") {
  for (Precision p : test::both_precisions) {
    const double tol = test::is_single(p) ? 1e-5 : 1e-8;
    INFO("precision " << capsule::choice_name(p));
    CHECK(couette_error<D3Q19>(4, 8, 3, 1.0 / 6.0, -0.05, 0.05, 2500, p) < tol);
    CHECK(couette_error<D3Q19>(3, 8, 2, 0.05, 0.0, 0.04, 8000, p) < tol);
  }
}
