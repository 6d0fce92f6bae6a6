// Plane Couette flow (walls at -+U) across a refined block: the exact linear profile
// u(y) = U (2 y / H - 1) must cross the coarse-fine interface.
#include <catch2/catch.hpp>

#include "tests/solver/lbm/refined_helpers.hpp"

using namespace capsule::lbm;
using namespace capsule::lbm::refinement;

namespace {

// Steady error max |u - exact| / U after `steps` coarse steps. The profile is odd about the
// centre, so only the even Stokes modes are excited, the slowest decaying like
// exp(-nu (2 pi/H)^2 t): H = 16, nu = 1/6 and 2000 steps give exp(-51); H = 12 and 600 steps exp(-27).
template <class L>
double couette_error(int nx, int ny, int nz, const BlockExtent& block, double U, int steps) {
  RefinedFluid<L> fluid(nx, ny, nz, 1.0 / 6.0, block);
  fluid.set_wall_velocity(-U, U);
  for (int s = 0; s < steps; ++s) fluid.step();
  return test::refined_velocity_error(fluid, [&](double, double y, double) {
           return std::array<double, 3>{U * (2.0 * y / ny - 1.0), 0.0, 0.0};
         }) /
         U;
}

}  // namespace

// A block spanning the periodic axes has plane faces only. There every exploded population
// stands for the coarse field at its own coarse row and every coalesced one likewise
// (explosion.hpp, coalescence.hpp), so the two lattices hold their exact solutions: round-off
// only. Measured 2e-15 (U = 0.05) and 2e-14 (U = 0.005; the populations' absolute round-off,
// ~1e-17, over a smaller U); bound 1e-12.
TEST_CASE("refined block with plane faces: Couette flow exact to round-off", "[lbm][refinement]") {
  for (double U : {0.05, 0.005}) {
    INFO("U = " << U);
    CHECK(couette_error<D2Q9>(4, 16, 1, BlockExtent{{0, 4, 0}, {4, 12, 1}}, U, 2000) < 1e-12);
    CHECK(couette_error<D3Q19>(2, 16, 2, BlockExtent{{0, 4, 0}, {2, 12, 2}}, U, 2000) < 1e-12);
  }
}

// A box block also has edges and corners, where the children of one coarse cell stand for the
// coarse field at different points. The half-spacing shifts and the Taylor terms make every term
// linear in U exact there too; what is left is quadratic in U (the equilibrium's u^2 terms enter
// the post-collision populations at second order in the gradient, with (tau - 1) dt differing
// between the levels). Measured max |u - exact| / U: 1.9e-4 at U = 0.05 and 1.8e-5 at U = 0.005
// (D2Q9, 12 x 16, block 6 x 8), 1.07e-4 and 1.06e-5 (D3Q19, 10 x 12 x 10, block 4^3): a factor
// 10 in U gives ~10 in |u - exact| / U (a defect linear in U would leave it unchanged, as it did
// without the shifts: 1.4e-3 at both U). Bounds: error / U < 0.01 U (2.6x the largest measured),
// and the ratio of error / U above 5.
TEST_CASE("refined box block: Couette flow exact to first order in U", "[lbm][refinement]") {
  const BlockExtent box2{{3, 4, 0}, {9, 12, 1}};
  const double e2_large = couette_error<D2Q9>(12, 16, 1, box2, 0.05, 2000);
  const double e2_small = couette_error<D2Q9>(12, 16, 1, box2, 0.005, 2000);
  CHECK(e2_large < 0.01 * 0.05);
  CHECK(e2_small < 0.01 * 0.005);
  CHECK(e2_large / e2_small > 5.0);
  const BlockExtent box3{{3, 4, 3}, {7, 8, 7}};
  const double e3_large = couette_error<D3Q19>(10, 12, 10, box3, 0.05, 600);
  const double e3_small = couette_error<D3Q19>(10, 12, 10, box3, 0.005, 600);
  CHECK(e3_large < 0.01 * 0.05);
  CHECK(e3_small < 0.01 * 0.005);
  CHECK(e3_large / e3_small > 5.0);
}
