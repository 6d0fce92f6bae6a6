// The rigid circle of immersed-boundary markers against exact 2D Stokes flow (a circular
// cylinder in simple shear): the stresslet 4 pi mu a^2 (k/2) per unit length, unchanged by a
// rigid rotation, and the free rotation k/2. At a = 4 (the CI size) in the 10a x 10a channel.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "solver/ib/hydrodynamic_radius.hpp"
#include "solver/rigid_sphere/rigid_circle.hpp"

using namespace capsule::rigid_sphere;

namespace {

RigidCircleOptions ci_circle(double spin, double kt) {
  RigidCircleOptions o;
  o.a = 4;
  o.domain[0] = o.domain[1] = 10;  // the channel in which the 2D gap was fitted
  o.spin = spin;
  o.kt = kt;
  o.every = 1;
  return o;
}

}  // namespace

TEST_CASE("rigid circle: freely rotating, a steady stresslet of a circle about 0.84 lattice units larger than its markers", "[rigid_sphere]") {
  const RigidShellResult free = run_rigid_circle(ci_circle(-0.5, 4));
  REQUIRE(free.series.size() == 4);
  const auto& last = free.series.back();
  INFO("stresslet " << last.stresslet << " one kt before " << free.series[2].stresslet << ", torque " << last.torque);
  // Steady: 0.02 % over the last kt measured.
  CHECK(std::abs(last.stresslet - free.series[2].stresslet) < 0.002 * last.stresslet);
  // Free: the anchors turn at the unbounded rate k/2 and the torque is the walls' small share
  // (-0.037 of the held circle's measured; 0.1 allowed).
  CHECK(std::abs(last.torque) < 0.1);
  // The radius the flow sees: S = C (a_S / a)^2 with the channel's own factor C = 1.040 at
  // 10a x 10a (fitted with the gap over a = 4-20, solver/ib/hydrodynamic_radius.hpp): a_S - a =
  // 0.844 measured, and the fitted gap d_S(4) = 0.49 + 1.41 / 4 = 0.84. The 0.1 allowed is
  // the fit's spread at this radius from a ladder that leaves it out (0.84-0.85) and C's
  // uncertainty (0.1 % in C moves a_S by 0.002).
  const double a_S = 4.0 * std::sqrt(last.stresslet / 1.040);
  const auto gap = capsule::ib::stresslet_radius_gap_2d(capsule::ib::Delta::peskin4);
  REQUIRE(gap);
  CHECK(a_S - 4.0 == Approx(gap->c0 + gap->c1 / 4.0).margin(0.1));
}

TEST_CASE("rigid circle: a rigid rotation adds no stresslet - holding the circle makes a torque of the sign of the flow's spin", "[rigid_sphere]") {
  // Held (spin 0) the tethered markers creep in their slow modes, so the held circle is read
  // early (kt 2), where its stresslet is 0.7 % below the free one's at a = 4.
  const RigidShellResult held = run_rigid_circle(ci_circle(0.0, 2));
  const RigidShellResult free = run_rigid_circle(ci_circle(-0.5, 2));
  const double S_held = held.series.back().stresslet, S_free = free.series.back().stresslet;
  INFO("stresslet held " << S_held << " free " << S_free << ", torque held " << held.series.back().torque);
  CHECK(std::abs(S_held / S_free - 1.0) < 0.015);
  CHECK(held.series.back().torque > 1.0);  // exact unbounded 1, the smeared circle larger
  CHECK(std::abs(held.series.back().torque) > 10 * std::abs(free.series.back().torque));
}

TEST_CASE("rigid circle: bad options are refused with the option's name and range", "[rigid_sphere]") {
  RigidCircleOptions o;
  o.a = 1;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("a must be in [2, 200]"));
  o = RigidCircleOptions{};
  o.segments = 8;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("segments must be in [16, 100000]"));
  o = RigidCircleOptions{};
  o.every = 0;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("every must be in (0, kt]"));
}
