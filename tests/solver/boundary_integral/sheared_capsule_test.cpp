// The boundary-integral capsule against the exact limits of small-deformation theory
// (neo-Hookean sphere, V = 1, unbounded shear; a = k = mu = 1):
//  - at kt -> 0 the membrane is unstressed and moves with the imposed flow, so the sphere
//    deforms affinely: D = kt/2 + O(kt^2), at any Ca;
//  - at steady state and Ca -> 0, D = (25/4) Ca at 45 degrees (Barthes-Biesel and Rallison 1981,
//    with this Ca = mu k a / E_s and G_s = E_s/3, docs/conventions.md "Neo-Hookean modulus").
// At level 2 (162 vertices) the discretisation error is second order and measured: D/Ca =
// 6.12 at Ca = 0.005 (-2.1 %); the tolerance 3.5 % allows for that error and no more.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <omp.h>

#include "solver/boundary_integral/sheared_capsule.hpp"

using namespace capsule::boundary_integral;

TEST_CASE("reference capsule: an unstressed sphere deforms with the imposed flow, D = kt/2", "[boundary_integral]") {
  ShearedCapsuleParameters p;
  p.Ca = 0.1;
  p.level = 2;
  p.dt = 0.002;
  ShearedCapsule capsule(p);
  while (capsule.kt() < 0.02 - 1e-12) capsule.step();
  const CapsuleShape s = capsule.shape();
  INFO("kt " << s.kt << " D " << s.D);
  // The relaxation (rate ~ 1/(12.5 Ca)) lowers D by kt/(25 Ca) relative = 0.8 % here; 2 % allows it.
  CHECK(std::abs(s.D / (0.5 * s.kt) - 1.0) < 0.02);
  CHECK(std::abs(s.theta - std::numbers::pi / 4) < 0.02);
}

TEST_CASE("reference capsule: small-deformation limit D = (25/4) Ca at 45 degrees", "[boundary_integral]") {
  ShearedCapsuleParameters p;
  p.Ca = 0.005;
  p.level = 2;
  ShearedCapsule capsule(p);
  while (capsule.kt() < 0.6) capsule.step();  // steady after kt ~ 0.3 (relaxation time 12.5 Ca / k)
  const CapsuleShape s = capsule.shape();
  INFO("D/Ca " << s.D / p.Ca << " theta " << s.theta);
  CHECK(std::abs(s.D / p.Ca / 6.25 - 1.0) < 0.035);
  // theta's O(Ca) departure from 45 degrees is 0.2 % here; the mesh's is the 0.03 rad measured.
  CHECK(std::abs(s.theta - std::numbers::pi / 4) < 0.05);
  CHECK(std::abs(s.volume_change) < 1e-6);  // the flux correction keeps the volume
}

TEST_CASE("reference capsule: the result does not depend on the thread count", "[boundary_integral]") {
  auto run = [](int threads) {
    omp_set_num_threads(threads);
    ShearedCapsuleParameters p;
    p.Ca = 0.1;
    p.level = 2;
    ShearedCapsule capsule(p);
    for (int n = 0; n < 20; ++n) capsule.step();
    return capsule.mesh().x;
  };
  const int threads = omp_get_max_threads();
  const auto one = run(1), two = run(2);
  omp_set_num_threads(threads);
  for (std::size_t i = 0; i < one.size(); ++i) CHECK(one[i] == two[i]);
}

TEST_CASE("reference capsule: bad parameters name themselves", "[boundary_integral]") {
  ShearedCapsuleParameters p;
  p.Ca = -1;
  CHECK_THROWS_WITH(ShearedCapsule(p), Catch::Contains("Ca must be > 0"));
  p.Ca = 0.1;
  p.level = 7;
  CHECK_THROWS_WITH(ShearedCapsule(p), Catch::Contains("mesh level must be 1-6"));
}
