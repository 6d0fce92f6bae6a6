// Why a viscosity contrast moved with tau, at the lattice level: a channel between walls at
// rest, its middle V = 5 times more viscous across a smoothed step (the indicator (15)-(16)
// of solver/ib/viscosity_contrast.hpp, h = 1), driven by a uniform body force plus a force
// concentrated on the two viscosity jumps (the shape of an immersed boundary's spread force,
// Peskin's 4-point kernel). At the same physical numbers (force scaled with nu, so the
// velocity in lattice units is the same), the steady profile must not depend on tau.
//  - CollisionModel::trt (odd moments at Lambda = 3/16 at every node): the steady TRT solution
//    depends on Lambda only, so the profiles at tau 0.7 and 1.5 agree to round-off; measured
//    8.7e-14 (D3Q19) and 4.9e-14 (D2Q9) relative, double; bound 1e-8.
//  - mrt in D3Q19 (the text's rates: q at s_nu, Lambda = (3 nu)^2, 0.04 to 25 here; m at 1.8):
//    measured 2.2e-2; demanded > 1e-3, so the test tells the two apart.
//  - mrt in D2Q9: the text's q rate (9), s_q = 3 (2 - s_nu)/(3 - s_nu), is exactly
//    Lambda = 1/12 at every s_nu, and every even moment relaxes at s_nu: D2Q9's MRT is a TRT
//    already, and measured 1.8e-14; bound 1e-8.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "solver/lbm/fluid.hpp"
#include "tests/solver/lbm/flow_helpers.hpp"

using namespace capsule::lbm;

namespace {

double heaviside(double d) {  // (15), h = 1
  if (d < -2.0) return 0.0;
  if (d > 2.0) return 1.0;
  return 0.5 * (1.0 + 0.5 * d + std::sin(0.5 * std::numbers::pi * d) / std::numbers::pi);
}

double peskin4(double r) {
  r = std::abs(r);
  if (r < 1.0) return (3.0 - 2.0 * r + std::sqrt(1.0 + 4.0 * r - 4.0 * r * r)) / 8.0;
  if (r < 2.0) return (5.0 - 2.0 * r - std::sqrt(-7.0 + 12.0 * r - 4.0 * r * r)) / 8.0;
  return 0.0;
}

// Steady u_x(y) with walls at y = 0 and H; inside |y - H/2| < w the viscosity is V nu.
template <class L>
std::vector<double> steady_profile(double tau, CollisionModel model) {
  constexpr int H = 24;
  constexpr double V = 5.0, w = 6.3, u_scale = 0.01;
  const double nu = (tau - 0.5) / 3.0;
  const int nz = L::D == 3 ? 2 : 1;
  Fluid<L> fluid(2, H, nz, nu, Precision::double_precision);
  fluid.set_collision(model);
  std::vector<double> F(H);
  for (int y = 0; y < H; ++y) {
    const double yc = y + 0.5, d = std::abs(yc - 0.5 * H) - w;  // d > 0 outside
    const double nu_y = V * nu + (nu - V * nu) * heaviside(d);
    for (int x = 0; x < 2; ++x)
      for (int z = 0; z < nz; ++z) fluid.set_viscosity(fluid.index(x, y, z), nu_y);
    // u ~ F H^2 / nu: the force scales with nu so that u is the same number at every tau.
    F[y] = u_scale * nu / (H * H) * (8.0 + 40.0 * (peskin4(yc - (0.5 * H - w)) - peskin4(yc - (0.5 * H + w))));
  }
  // Slowest transient ~ exp(-nu pi^2 t / H^2) (the outer, least viscous layer bounds it).
  const int steps = int(40.0 * H * H / (std::numbers::pi * std::numbers::pi * nu));
  for (int s = 0; s < steps; ++s) {
    for (int z = 0; z < nz; ++z)
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < 2; ++x) fluid.force(0)[fluid.index(x, y, z)] = F[y];
    fluid.step();
  }
  return test::velocity_profile(fluid);
}

template <class L>
double tau_change(CollisionModel model) {
  const auto a = steady_profile<L>(0.7, model), b = steady_profile<L>(1.5, model);
  double worst = 0, scale = 0;
  for (std::size_t y = 0; y < a.size(); ++y) {
    worst = std::max(worst, std::abs(a[y] - b[y]));
    scale = std::max(scale, std::abs(a[y]));
  }
  return worst / scale;
}

}  // namespace

TEST_CASE("A forced channel with a viscosity contrast: steady flow independent of tau with trt (and 2D mrt), not with 3D mrt", "[lbm]") {
  const double trt3 = tau_change<D3Q19>(CollisionModel::trt), mrt3 = tau_change<D3Q19>(CollisionModel::mrt);
  const double trt2 = tau_change<D2Q9>(CollisionModel::trt), mrt2 = tau_change<D2Q9>(CollisionModel::mrt);
  INFO("largest change tau 0.7 -> 1.5, relative: D3Q19 trt " << trt3 << " mrt " << mrt3 << "; D2Q9 trt " << trt2
                                                              << " mrt " << mrt2);
  CHECK(trt3 < 1e-8);
  CHECK(trt2 < 1e-8);
  CHECK(mrt3 > 1e-3);
  CHECK(mrt2 < 1e-8);
}
