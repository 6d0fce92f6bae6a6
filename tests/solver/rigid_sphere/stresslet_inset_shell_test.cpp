// The calibration's own exact problem at CI size: a rigid shell of markers on the radius the
// stresslet's inset gives (solver/ib/hydrodynamic_radius.hpp) exerts the stresslet of a sphere
// of radius a, (10/3) pi mu a^3 k (Batchelor 1970), times the box's own correction; with the
// markers on a it exerts that of a sphere about 0.5-0.7 lattice units larger.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "solver/ib/hydrodynamic_radius.hpp"
#include "solver/rigid_sphere/rigid_shell.hpp"

using namespace capsule;
using namespace capsule::rigid_sphere;

namespace {

double stresslet(ib::Delta delta, double a, double marker_radius) {
  RigidShellOptions o;
  o.a = a;
  o.marker_radius = marker_radius;
  o.level = 3;
  o.delta = delta;
  o.gain = 0.05;
  o.kt = 1.5;
  o.every = 0.5;
  return run_rigid_shell(o).series.back().stresslet;
}

}  // namespace

TEST_CASE("with the stresslet's inset a rigid shell of markers exerts the stresslet of the sphere of radius a", "[rigid_sphere]") {
  // The box's walls 5a away raise the stresslet by 0.88 % (a = 4 in boxes 10a to 30a wide,
  // docs/findings/immersed_boundary_error_budget.md "The exact problems: a rigid shell of markers").
  const double box = 1.0088;
  const double a = 5;
  // The default kernel on a and with its inset; Peskin's and Keys' kernels with their own.
  const double roma3_on_a = a * std::cbrt(stresslet(ib::Delta::roma3, a, a) / box) - a;
  INFO("roma3: a_S - a with the markers on a " << roma3_on_a);
  CHECK(roma3_on_a > 0.4);  // measured 0.51 at kt 2 (peskin4 0.72)
  for (const ib::Delta delta : {ib::Delta::roma3, ib::Delta::peskin4, ib::Delta::keys4}) {
    const double inset = ib::stresslet_marker_inset(*ib::stresslet_radius_gap(delta), a);
    // The radius of the sphere that exerts it: S = (a_S / a)^3 times the box's correction.
    const double gap_inset = a * std::cbrt(stresslet(delta, a, a - inset) / box) - a;
    INFO(choice_name(delta) << ": inset " << inset << ", a_S - a with the inset " << gap_inset);
    // The fit reproduces its measured radii within 0.005 node; kt 1.5 instead of 2 and the
    // box correction's own error (measured at a = 4) add a few hundredths: 0.05 node is 3 %
    // of the stresslet at a = 5, a tenth of the gap the inset removes.
    CHECK(std::abs(gap_inset) < 0.05);
  }
}
