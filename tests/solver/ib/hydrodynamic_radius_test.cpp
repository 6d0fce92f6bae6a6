// The stresslet's marker inset (solver/ib/hydrodynamic_radius.hpp): the rule solves
// r_m + d_S(r_m) = a, gives the insets the error budget measured capsules with, and refuses
// what it cannot solve.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/ib/hydrodynamic_radius.hpp"

using namespace capsule::ib;

TEST_CASE("the stresslet's marker inset puts the shell's hydrodynamic radius on a", "[ib]") {
  const auto roma3 = stresslet_radius_gap(Delta::roma3);
  const auto peskin4 = stresslet_radius_gap(Delta::peskin4);
  const auto keys4 = stresslet_radius_gap(Delta::keys4);
  REQUIRE(roma3);
  REQUIRE(peskin4);
  REQUIRE(keys4);
  CHECK_FALSE(stresslet_radius_gap(Delta::cosine));
  CHECK_FALSE(stresslet_radius_gap(Delta::linear2));
  for (double a : {3.0, 5.0, 7.0, 10.0, 14.0, 40.0}) {
    for (const auto& g : {*roma3, *peskin4, *keys4}) {
      const double inset = stresslet_marker_inset(g, a);
      const double r = a - inset;
      // The defining equation, to round-off.
      CHECK(std::abs(r + g.c0 + g.c1 / r - a) < 1e-12 * a);
      // The larger root: the inset tends to c0 as a grows.
      CHECK(inset > g.c0);
      CHECK(inset < g.c0 + 2.0 * g.c1 / a + 1e-12);
    }
  }
  // The insets docs/findings/immersed_boundary_error_budget.md ran capsules with (two decimals;
  // peskin4 at a = 5 ran 0.75 against the rule's 0.766).
  CHECK(stresslet_marker_inset(*roma3, 5) == Approx(0.53).margin(0.005));
  CHECK(stresslet_marker_inset(*roma3, 7) == Approx(0.47).margin(0.005));
  CHECK(stresslet_marker_inset(*roma3, 10) == Approx(0.43).margin(0.005));
  CHECK(stresslet_marker_inset(*peskin4, 5) == Approx(0.766).margin(0.005));
  CHECK(stresslet_marker_inset(*peskin4, 7) == Approx(0.66).margin(0.005));
  CHECK(stresslet_marker_inset(*peskin4, 10) == Approx(0.59).margin(0.005));
  CHECK(stresslet_marker_inset(*keys4, 7) == Approx(0.20).margin(0.005));
  CHECK(stresslet_marker_inset(*keys4, 10) == Approx(0.17).margin(0.005));
  // Below the smallest radius there is no root.
  CHECK(std::isnan(stresslet_marker_inset(*roma3, 0.9 * stresslet_inset_min_radius(*roma3))));
  CHECK_FALSE(std::isnan(stresslet_marker_inset(*roma3, stresslet_inset_min_radius(*roma3))));
}
