// The immersed boundary on the fine level of a refined fluid in 3D (solver/lbm/refinement/,
// solver/rigid_sphere/tethered_markers.cpp): the rigid spherical shell (`capsule rigid-sphere
// --refine-margin`) inside a block refined by a factor 2 against the same shell on the uniform
// lattices at the fine and at the coarse spacing (the fine lattice's a = 6, the coarse one's 3,
// level 3, the 3D capsule's 10a x 10a x 8a box, 1 kt from the Couette flow).
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/rigid_sphere/rigid_shell.hpp"

using namespace capsule::rigid_sphere;

namespace {

RigidShellOptions shell(double a, int refine_margin) {
  RigidShellOptions o;
  o.a = a;
  o.kt = 1;
  o.every = 1;
  o.refine_margin = refine_margin;
  return o;
}

const RigidShellRow& last(const RigidShellResult& r) { return r.series.back(); }

}  // namespace

TEST_CASE("refined fluid: a rigid sphere in the fine block exerts the uniform fine lattice's torque and stresslet", "[rigid_sphere][refinement]") {
  const RigidShellResult fine = run_rigid_shell(shell(6, 0));
  const RigidShellResult refined = run_rigid_shell(shell(6, 3));
  const RigidShellResult coarse = run_rigid_shell(shell(3, 0));
  const double torque_fine = last(fine).torque, stresslet_fine = last(fine).stresslet;
  INFO("torque fine " << torque_fine << ", refined " << last(refined).torque << ", coarse " << last(coarse).torque);
  INFO("stresslet fine " << stresslet_fine << ", refined " << last(refined).stresslet << ", coarse " << last(coarse).stresslet);
  CHECK(refined.steps == fine.steps);
  CHECK(last(refined).kt == Approx(last(fine).kt));
  // Within 1 %, as the rigid circle: what is left is the interface's (the explosion's missing
  // time interpolation, the ring's O(U^2) edge terms; docs/findings/refinement.md). Measured
  // 2026-12-08: torque 1.27245 against 1.27082 (+0.13 %), stresslet 1.39268 against 1.38631
  // (+0.46 %); the uniform coarse lattice (a = 3) is +34 % and +56 % off, and the block recovers
  // more than 90 % of that (99 % measured).
  CHECK(std::abs(last(refined).torque - torque_fine) < 0.01 * torque_fine);
  CHECK(std::abs(last(refined).stresslet - stresslet_fine) < 0.01 * stresslet_fine);
  CHECK(std::abs(last(refined).torque - torque_fine) < 0.1 * std::abs(last(coarse).torque - torque_fine));
  CHECK(std::abs(last(refined).stresslet - stresslet_fine) < 0.1 * std::abs(last(coarse).stresslet - stresslet_fine));
}

TEST_CASE("refined fluid: a rigid sphere refused with an odd fine box, a margin out of range or single precision", "[rigid_sphere][refinement]") {
  RigidShellOptions o = shell(6, 3);
  o.domain[2] = 8.5;  // 51 fine nodes
  CHECK_THROWS_WITH(validate(o), Catch::Contains("even number of fine nodes per axis"));
  o = shell(6, 21);
  CHECK_THROWS_WITH(validate(o), Catch::Contains("refine_margin must be in [0, 20]"));
  o = shell(6, 3);
  o.precision = capsule::lbm::Precision::single_precision;
  CHECK_THROWS_WITH(validate(o), Catch::Contains("holds its populations in double"));
  // A block that, with the three coarse cells the transfers need, leaves the box.
  o = shell(6, 12);
  CHECK_THROWS_WITH(run_rigid_shell(o), Catch::Contains("refined block"));
}
