// The rigid shell of immersed-boundary markers against exact Stokes flow (a sphere in simple
// shear, Batchelor 1970): the torque 4 pi mu a^3 k (1 + 2 spin) is linear in the spin, its zero
// is the free rotation k/2, and a rigid rotation adds no stresslet. At a = 3 (the CI size) the
// smeared shell's torque is that of a sphere about 0.55 lattice units larger than its markers
// (docs/findings/immersed_boundary_error_budget.md measures 0.58 / 0.54 / 0.52 at a = 3 / 4 / 5).
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "solver/rigid_sphere/rigid_shell.hpp"

using namespace capsule::rigid_sphere;

namespace {

RigidShellOptions ci_shell(double spin, double gain) {
  RigidShellOptions o;
  o.a = 3;
  o.level = 2;  // 162 markers, 0.84 lattice units apart (the capsule's meshes: 0.5-1)
  o.domain = {8, 8, 6};
  o.spin = spin;
  o.gain = gain;
  o.kt = 1.5;
  o.every = 0.5;
  return o;
}

}  // namespace

TEST_CASE("rigid shell: steady, independent of the tether gain, a hydrodynamic radius about half a node larger", "[rigid_sphere]") {
  const RigidShellResult held = run_rigid_shell(ci_shell(0.0, 0.2));
  const RigidShellResult stiffer = run_rigid_shell(ci_shell(0.0, 0.4));
  REQUIRE(held.series.size() == 3);
  const auto& last = held.series.back();
  INFO("torque " << last.torque << " one kt before " << held.series[0].torque << " stresslet " << last.stresslet);
  // Steady: the torque moves by 0.2 % over the last kt at this gain (the marker lattice's slow modes).
  CHECK(std::abs(last.torque - held.series[0].torque) < 0.005 * last.torque);
  // Once steady every marker moves with its anchor, whatever force per unit lag: 0.15 % measured.
  CHECK(std::abs(stiffer.series.back().torque / last.torque - 1.0) < 0.005);
  // The markers are held: their interpolated velocity is at most a few per mille of k a.
  CHECK(last.slip_rms < 0.01);
  // Hydrodynamic radius from the torque: a_T = a T^(1/3); the box's own correction to T is
  // 0.05 % (measured with 1.5-3 times larger boxes at a = 4), so a_T - a is the lattice's.
  const double offset = 3.0 * (std::cbrt(last.torque) - 1.0);
  INFO("a_T - a = " << offset);
  CHECK(offset > 0.4);
  CHECK(offset < 0.75);
}

TEST_CASE("rigid shell: the torque is linear in the spin, zero near the free rotation k/2, and rotation adds no stresslet", "[rigid_sphere]") {
  const RigidShellResult held = run_rigid_shell(ci_shell(0.0, 0.2));
  const RigidShellResult reversed = run_rigid_shell(ci_shell(-1.0, 0.2));
  REQUIRE(reversed.torque_exact == -1.0);
  const double T0 = held.series.back().torque, T1 = reversed.series.back().torque;
  // T(spin) = T0 + B spin; the free rotation is where T = 0.
  const double free_spin = -T0 / (T0 - T1);
  INFO("T(0) " << T0 << " T(-1) " << T1 << " free spin " << free_spin);
  // Exact: -1/2 in unbounded flow; the walls 4a away slow a free sphere by O((a/h)^3) per wall
  // (Goldman, Cox and Brenner 1967) and the lattice adds its own: 1.8 % measured; 3 % allowed.
  CHECK(std::abs(free_spin / -0.5 - 1.0) < 0.03);
  // A rigid rotation is antisymmetric: the stresslet must not depend on the spin (0.6 % measured,
  // the markers' slightly different lag).
  const double S0 = held.series.back().stresslet, S1 = reversed.series.back().stresslet;
  INFO("stresslet held " << S0 << " reversed " << S1);
  CHECK(std::abs(S1 / S0 - 1.0) < 0.015);
  CHECK(S0 > 1.0);  // the straining flow is resisted: the sign of the particle stress
}

TEST_CASE("rigid shell: bad options are refused with the option's name and range", "[rigid_sphere]") {
  RigidShellOptions o;
  o.a = 1;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("a must be in [2, 64]"));
  o = RigidShellOptions{};
  o.gain = 0;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("gain must be in (0, 1]"));
  o = RigidShellOptions{};
  o.every = 0;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("every must be in (0, kt]"));
}
