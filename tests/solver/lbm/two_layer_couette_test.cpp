// Two-layer Couette flow with the per-node viscosity field: nu_1 below y = H/2, nu_2
// above. Continuity of the shear stress rho nu du/dy makes the profile piecewise linear
// with slope ratio a_1 / a_2 = nu_2 / nu_1, and a_1 H/2 + a_2 H/2 = u_top - u_bottom.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/lbm/fluid.hpp"
#include "tests/solver/lbm/flow_helpers.hpp"

using namespace capsule::lbm;

namespace {

// nx > 2 with perturb: start from a velocity field that varies in x (amplitude 1e-3),
// which seeds every 2D mode; an x-uniform start cannot excite an unstable 2D mode of the
// scheme (the large-tau instability of relaxation.hpp went unnoticed that way).
template <class L>
void check_two_layers_in(double nu1, double nu2, int nx, bool perturb, Precision prec) {
  const int H = 16, nz = L::D == 3 ? 2 : 1;
  const double U = 0.04;
  Fluid<L> fluid(nx, H, nz, nu2, prec);
  // Single precision: the profile is exact to float round-off, but the checks take
  // differences of neighbouring velocities, up to 100x smaller than the velocities (slope
  // 4.5e-4 per node against |u| up to 0.04 in the nu = 5/3 layer), so float's ~1e-7 of u is
  // ~1e-5 of a difference (measured up to 2.3e-5): bound 1e-4 instead of 1e-9.
  const double tol = test::is_single(prec) ? 1e-4 : 1e-9;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < H / 2; ++y)
      for (int x = 0; x < nx; ++x) fluid.set_viscosity(fluid.index(x, y, z), nu1);
  REQUIRE(fluid.viscosity(fluid.index(1, H / 2 - 1, nz - 1)) == nu1);
  REQUIRE(fluid.viscosity(fluid.index(1, H / 2, nz - 1)) == nu2);
  if (perturb)
    fluid.initialise_velocity([&](double x, double y, double) {
      const double s = std::sin(2.0 * M_PI * x / nx) * std::sin(M_PI * y / H);
      return std::array<double, 3>{1e-3 * s, 1e-3 * std::cos(4.0 * M_PI * x / nx) * s, 0.0};
    });
  fluid.set_wall_velocity(0.0, U);
  // Slowest transient ~ exp(-min(nu) (pi/H)^2 t) (bounded by the lower viscosity);
  // 30 / (min nu (pi/H)^2) steps leave exp(-30) ~ 1e-13 of it. The x-dependent part of a
  // perturbed start decays faster still (larger wave number).
  const int steps = int(30.0 / (std::min(nu1, nu2) * std::pow(M_PI / H, 2)));
  for (int s = 0; s < steps; ++s) fluid.step();
  const auto u = test::velocity_profile(fluid);

  const double a1 = 2.0 * U * nu2 / (H * (nu1 + nu2));
  const double a2 = 2.0 * U * nu1 / (H * (nu1 + nu2));
  // Measured slopes from differences well inside each layer (2 nodes from the interface).
  const double s1 = (u[H / 2 - 3] - u[1]) / (H / 2 - 4);
  const double s2 = (u[H - 2] - u[H / 2 + 2]) / (H / 2 - 4);
  INFO("precision " << capsule::choice_name(prec) << " nu1 " << nu1 << " nu2 " << nu2 << " slopes " << s1 << " " << s2 << " exact " << a1 << " " << a2
              << " ratio " << s1 / s2 << " exact " << nu2 / nu1);
  // Linear within each layer: every difference inside a layer equals its slope (1e-9 relative:
  // the converged profile is exactly piecewise linear up to the decayed transient).
  for (int y = 1; y < H / 2 - 3; ++y) CHECK(std::abs((u[y + 1] - u[y]) / s1 - 1.0) < tol);
  for (int y = H / 2 + 2; y < H - 2; ++y) CHECK(std::abs((u[y + 1] - u[y]) / s2 - 1.0) < tol);
  // Slope ratio nu2/nu1: a sharp jump between two node rows is a stress balance across one
  // link, so the ratio comes out to round-off; 1e-9 bounds the decayed transient.
  CHECK(std::abs((s1 / s2) / (nu2 / nu1) - 1.0) < tol);
  // Slopes against the analytic values with the interface at y = H/2. The interface sits
  // half-way between the node rows H/2-1 and H/2 like the walls, so this is exact too.
  CHECK(std::abs(s1 / a1 - 1.0) < tol);
  CHECK(std::abs(s2 / a2 - 1.0) < tol);
}

template <class L>
void check_two_layers(double nu1, double nu2, int nx = 2, bool perturb = false) {
  for (Precision p : test::both_precisions) check_two_layers_in<L>(nu1, nu2, nx, perturb, p);
}

}  // namespace

TEST_CASE("Two-layer Couette flow with a per-node viscosity field (D2Q9)", "[lbm]") {
  check_two_layers<D2Q9>(0.2, 0.05);
  check_two_layers<D2Q9>(0.05, 0.15);
}

TEST_CASE("Two-layer Couette flow with a per-node viscosity field (D3Q19)", "[lbm]") {
  check_two_layers<D3Q19>(0.2, 0.05);
}

// Viscosity ratio 10 between nu = 1/6 (tau = 1) and 5/3 (tau = 5.5), the dissertation's
// largest V, started from a perturbed field. With the old rates (s_eps fixed,
// relaxation.hpp) the tau = 5.5 layer blew up: at step 801 / 842 (D2Q9, 16 columns; 8
// columns were too few to hold the growing waves) and 465 (D3Q19, 4 x 2 columns). The
// tolerances are those of check_two_layers: the profile is exact up to round-off.
TEST_CASE("Two-layer Couette flow with viscosity ratio 10 from a perturbed start (D2Q9)", "[lbm]") {
  check_two_layers<D2Q9>(1.0 / 6.0, 5.0 / 3.0, 16, true);
  check_two_layers<D2Q9>(5.0 / 3.0, 1.0 / 6.0, 16, true);
}

TEST_CASE("Two-layer Couette flow with viscosity ratio 10 from a perturbed start (D3Q19)", "[lbm]") {
  check_two_layers<D3Q19>(1.0 / 6.0, 5.0 / 3.0, 4, true);
}
