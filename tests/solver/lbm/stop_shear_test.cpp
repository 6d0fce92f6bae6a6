// Stopping the shear: after Couette flow reaches steady state the walls stop (wall
// velocity 0). The flow must decay monotonically to rest, and the total mass (sum of
// all populations) must stay constant to round-off throughout: shear, stop, decay,
// with and without a body force.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/lbm/fluid.hpp"
#include "tests/solver/lbm/flow_helpers.hpp"

using namespace capsule::lbm;

namespace {

template <class L>
void check_stop(int nx, int ny, int nz, bool with_force, Precision prec) {
  const double nu = 1.0 / 6.0;
  Fluid<L> fluid(nx, ny, nz, nu, prec);
  INFO("precision " << capsule::choice_name(prec));
  const bool single = test::is_single(prec);
  const double mass0 = fluid.total_mass();
  REQUIRE(mass0 == Approx(double(fluid.size())).epsilon(1e-14));  // rho = 1 everywhere at rest
  double worst_drift = 0.0;
  auto track_mass = [&] { worst_drift = std::max(worst_drift, std::abs(fluid.total_mass() / mass0 - 1.0)); };

  // A localised force pair with zero net force (like a membrane's), stirring the flow.
  auto apply_force = [&](int s) {
    fluid.clear_force();
    if (!with_force) return;
    const double F = 1e-5 * std::sin(0.01 * s);
    fluid.force(1)[fluid.index(nx / 2, ny / 2, nz / 2)] = F;
    fluid.force(1)[fluid.index(nx / 2 + 1, ny / 2, nz / 2)] = -F;
  };

  const double U = 0.05;
  fluid.set_wall_velocity(-U, U);
  const int shear_steps = int(20.0 / (nu * std::pow(M_PI / ny, 2)));  // steady to exp(-20)
  for (int s = 0; s < shear_steps; ++s) {
    apply_force(s);
    fluid.step();
    track_mass();
  }
  const double e_sheared = test::kinetic_energy(fluid);
  REQUIRE(e_sheared > 0.0);

  // Stop: walls at rest. Energy must fall monotonically (sampled every 50 steps, longer
  // than the acoustic time ny/c_s ~ 30 steps, so pressure waves cannot masquerade).
  fluid.set_wall_velocity(0.0, 0.0);
  fluid.clear_force();
  double previous = e_sheared;
  const int decay_steps = int(15.0 / (nu * std::pow(M_PI / ny, 2)));
  for (int s = 1; s <= decay_steps; ++s) {
    fluid.step();
    track_mass();
    if (s % 50 == 0) {
      const double e = test::kinetic_energy(fluid);
      // Checked while the energy is above 1e-15 of e_sheared. Below that it stagnates at a
      // floor: round-off (~1e-29 of e_sheared without force), or, with the adjacent +F/-F
      // pair, the lattice's undamped staggered mode u_x ~ (-1)^(x+t) that the pair excites
      // at ~6e-11 U (measured energy floor 1e-21 (2D) and 1e-18 (3D) of e_sheared). That mode
      // is exactly an equilibrium after every streaming step, so no collision damps it.
      // Single precision: the velocity floor is float round-off, ~1e-7 U, i.e. 1e-14 of the
      // energy; checked above 1e-10 of it.
      if (previous > (single ? 1e-10 : 1e-15) * e_sheared) CHECK(e < previous);
      previous = e;
    }
  }
  // The slowest mode decays as exp(-nu (pi/ny)^2 t) in amplitude, so the energy as exp(-30)
  // ~ 1e-13; 1e-12 leaves margin for the mode mix and sits far above the floors above.
  // Single precision ends at its round-off floor: bound 1e-9 (a decay by 9 orders).
  CHECK(previous / e_sheared < (single ? 1e-9 : 1e-12));
  // Round-off: the mass is a sum of ~Q * size() numbers, each step adds a relative
  // error of a few 1e-16 at most; 1e-12 over thousands of steps is round-off, while
  // a single unbalanced wall population would change it by ~1e-6.
  INFO("worst relative mass drift " << worst_drift);
  // Single precision: each step rounds every float population (~6e-8 of f_i - w_i ~ 1e-3),
  // a random walk of ~1e-10 per node and step; over ~10^4 steps and ~10^3 nodes the relative
  // drift stays below 1e-7 (the mass, rho = 1 + sum of the shifted populations, is summed in
  // double).
  CHECK(worst_drift < (single ? 1e-7 : 1e-12));
}

}  // namespace

TEST_CASE("Stopping the shear: the flow decays and mass is conserved (D2Q9)", "[lbm]") {
  for (Precision p : test::both_precisions) {
    check_stop<D2Q9>(16, 16, 1, false, p);
    check_stop<D2Q9>(16, 16, 1, true, p);
  }
}

TEST_CASE("Stopping the shear: the flow decays and mass is conserved (D3Q19)", "[lbm]") {
  for (Precision p : test::both_precisions) check_stop<D3Q19>(6, 12, 4, true, p);
}
