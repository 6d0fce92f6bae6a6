// Immersed-boundary operators (17)-(21) and the viscosity-contrast field (15)-(16).
#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <random>
#include <vector>

#include "solver/ib/grid.hpp"
#include "solver/ib/delta.hpp"
#include "solver/ib/interpolation.hpp"
#include "solver/ib/layer_spreading.hpp"
#include "solver/ib/membrane_update.hpp"
#include "solver/ib/spreading_box.hpp"
#include "solver/ib/viscosity_contrast.hpp"

using namespace capsule::ib;

TEST_CASE("cosine delta: partition of unity for arbitrary offsets", "[ib]") {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (int t = 0; t < 1000; ++t) {
    const double x = u(rng);
    const DeltaStencil1D s = delta_stencil(x);
    double sum = 0, direct = 0;
    for (int m = 0; m < 4; ++m) {
      sum += s.w[m];
      // the stencil weights are the kernel (18) evaluated at the node offsets
      direct += cosine_delta(x - (s.first + m + 0.5));
      REQUIRE(s.w[m] == Approx(cosine_delta(x - (s.first + m + 0.5))).margin(1e-14));  // rounding only
    }
    REQUIRE(sum == Approx(1.0).margin(1e-14));     // exact identity cos + sin - cos - sin = 0; rounding only
    REQUIRE(direct == Approx(1.0).margin(1e-14));  // the nodes outside the stencil carry zero weight
  }
}

TEST_CASE("cosine delta: first moment vanishes only on nodes and midway, bounded elsewhere", "[ib]") {
  // The cosine kernel (18) does not have a zero first moment (Peskin's sqrt kernel does).
  // Measured against the closed form: zero at r0 = 1 (on a node) and r0 = 1.5 (midway),
  // maximal 0.0209 dx near r0 = 1.214.
  double worst = 0;
  for (int t = 0; t <= 1000; ++t) {
    const double x = 7.5 + t / 1000.0;  // one full cell of offsets
    const DeltaStencil1D s = delta_stencil(x);
    double m1 = 0;
    for (int m = 0; m < 4; ++m) m1 += s.w[m] * (x - (s.first + m + 0.5));
    const double r0 = x - (s.first + 0.5);
    REQUIRE(m1 == Approx(first_moment_error(r0)).margin(1e-13));  // closed form, rounding only
    worst = std::max(worst, std::abs(m1));
  }
  REQUIRE(std::abs(first_moment_error(1.0)) < 1e-15);
  REQUIRE(std::abs(first_moment_error(1.5)) < 1e-15);
  REQUIRE(worst == Approx(0.0209).margin(2e-4));  // analytic maximum 0.02090 at r0 = 1.2143
}

TEST_CASE("interpolation: constant field exact, linear field exact up to the kernel first moment", "[ib]") {
  const Grid g{32, 24, 1};
  std::vector<double> ux(g.size()), uy(g.size());
  const double gx = 0.01, gy = -0.02, c = 0.3;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      ux[g.index(i, j)] = c + gx * (i + 0.5) + gy * (j + 0.5);  // linear in x and y
      uy[g.index(i, j)] = c;
    }
  const double* u[2] = {ux.data(), uy.data()};
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> px(8.0, 24.0), py(6.0, 18.0);
  for (int t = 0; t < 200; ++t) {
    const double X[2] = {px(rng), py(rng)};
    double U[2];
    interpolate<2>(g, u, X, 1, U);
    REQUIRE(U[1] == Approx(c).margin(1e-14));  // partition of unity: rounding only
    const DeltaStencil1D sx = delta_stencil(X[0]), sy = delta_stencil(X[1]);
    // u(X) - sum w u = gx m1(x) + gy m1(y): the first-moment error, nothing else.
    const double expected = c + gx * (X[0] - first_moment_error(X[0] - sx.first - 0.5)) +
                            gy * (X[1] - first_moment_error(X[1] - sy.first - 0.5));
    REQUIRE(U[0] == Approx(expected).margin(1e-13));  // rounding only
  }
  // On a node and midway between nodes the linear field is interpolated exactly.
  for (double X0 : {10.5, 11.0}) {
    const double X[2] = {X0, 12.0};
    double U[2];
    interpolate<2>(g, u, X, 1, U);
    REQUIRE(U[0] == Approx(c + gx * X[0] + gy * X[1]).margin(1e-14));
  }
}

TEST_CASE("spreading conserves the total force, periodic in x", "[ib]") {
  const Grid g{20, 16, 1};
  std::vector<double> px(g.size(), 0.0), py(g.size(), 0.0);
  double* p[2] = {px.data(), py.data()};
  // nodes anywhere away from the walls, including across the periodic x boundary
  const std::vector<double> X = {0.2, 5.3, 19.9, 8.7, 10.1, 12.4, 3.3, 2.5};
  const std::vector<double> F = {1.0, -2.0, 0.5, 0.25, -0.75, 3.0, 2.0, 1.0};
  spread<2>(g, X.data(), F.data(), 4, p);
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    sx += px[i];
    sy += py[i];
  }
  REQUIRE(sx == Approx(1.0 + 0.5 - 0.75 + 2.0).margin(1e-13));  // rounding only
  REQUIRE(sy == Approx(-2.0 + 0.25 + 3.0 + 1.0).margin(1e-13));
  // periodic: a node at x = 0.2 reaches nodes i = nx-2, nx-1 on the other side
  REQUIRE(px[g.index(g.nx - 1, 5)] != 0.0);
}

TEST_CASE("spreading is the adjoint of interpolation (3D)", "[ib]") {
  // sum_j p(x_j) . u(x_j) = sum_c P_c . U_c: the same weights both ways, so the
  // coupling neither creates nor destroys energy.
  const Grid g{12, 10, 8};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  std::vector<double> u0(g.size()), u1(g.size()), u2(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    u0[i] = r(rng);
    u1[i] = r(rng);
    u2[i] = r(rng);
  }
  const double* u[3] = {u0.data(), u1.data(), u2.data()};
  const std::size_t n = 5;
  std::vector<double> X(3 * n), P(3 * n), U(3 * n);
  for (std::size_t c = 0; c < n; ++c) {
    X[3 * c] = 6 + 6 * r(rng);
    X[3 * c + 1] = 5 + 2 * r(rng);
    X[3 * c + 2] = 4 + 4 * r(rng);
    for (int d = 0; d < 3; ++d) P[3 * c + d] = r(rng);
  }
  interpolate<3>(g, u, X.data(), n, U.data());
  std::vector<double> p0(g.size()), p1(g.size()), p2(g.size());
  double* p[3] = {p0.data(), p1.data(), p2.data()};
  spread<3>(g, X.data(), P.data(), n, p);
  double lhs = 0, rhs = 0, total_z = 0, Pz = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    lhs += p0[i] * u0[i] + p1[i] * u1[i] + p2[i] * u2[i];
    total_z += p2[i];
  }
  for (std::size_t i = 0; i < 3 * n; ++i) rhs += P[i] * U[i];
  for (std::size_t c = 0; c < n; ++c) Pz += P[3 * c + 2];
  REQUIRE(lhs == Approx(rhs).margin(1e-12));      // rounding only
  REQUIRE(total_z == Approx(Pz).margin(1e-12));   // conservation in 3D, periodic z
}

TEST_CASE("smoothed Heaviside (15) and viscosity (16)", "[ib]") {
  REQUIRE(smoothed_heaviside(-2.5) == 0.0);
  REQUIRE(smoothed_heaviside(2.5) == 1.0);
  REQUIRE(smoothed_heaviside(0.0) == Approx(0.5).margin(1e-15));
  REQUIRE(smoothed_heaviside(-2.0) == Approx(0.0).margin(1e-15));  // continuous at the band edges
  REQUIRE(smoothed_heaviside(2.0) == Approx(1.0).margin(1e-15));
  for (double d = -1.9; d < 2.0; d += 0.1)  // H(d) + H(-d) = 1 (odd part), monotone
    REQUIRE(smoothed_heaviside(d) + smoothed_heaviside(-d) == Approx(1.0).margin(1e-14));
  REQUIRE(contrast_viscosity(-3.0, 0.1, 0.5) == 0.5);
  REQUIRE(contrast_viscosity(3.0, 0.1, 0.5) == Approx(0.1).margin(1e-15));  // mu_c + (mu_a - mu_c): rounding
}

TEST_CASE("viscosity contrast: circle gives mu_c inside, mu_a outside, smooth band", "[ib]") {
  const Grid g{64, 48, 1};
  const double R = 10.0, cx = 32.0, cy = 24.0;
  const int n = 140;
  std::vector<double> X(2 * n), N(2 * n);
  for (int c = 0; c < n; ++c) {
    const double phi = 2 * std::numbers::pi * c / n;
    N[2 * c] = std::cos(phi);
    N[2 * c + 1] = std::sin(phi);
    X[2 * c] = cx + R * N[2 * c];
    X[2 * c + 1] = cy + R * N[2 * c + 1];
  }
  const double nu_a = 1.0 / 6, nu_c = 5.0 / 6;
  ViscosityContrast<2> vc(g, nu_a, nu_c);
  std::vector<double> nu(g.size(), -1.0);
  std::size_t calls = 0;
  vc.update(X.data(), N.data(), n, [&](std::size_t node, double v) { nu[node] = v; ++calls; });
  REQUIRE(calls >= g.size());  // first call sets every node
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double r = std::hypot(i + 0.5 - cx, j + 0.5 - cy);
      const double v = nu[g.index(i, j)];
      const double exact = contrast_viscosity(r - R, nu_a, nu_c);
      // nearest-node normal distance vs exact distance: node spacing 2 pi R / 140 = 0.45,
      // chord sagitta and angular offset give |d - (r - R)| < 0.03 here; dH/dd <= 1/2,
      // so the viscosity differs by at most 0.015 (nu_c - nu_a) -> 0.01
      REQUIRE(v == Approx(exact).margin(0.02 * (nu_c - nu_a)));
    }
  // moving the circle by one lattice unit updates only nodes near the membrane
  for (int c = 0; c < n; ++c) X[2 * c] += 1.0;
  calls = 0;
  vc.update(X.data(), N.data(), n, [&](std::size_t node, double v) { nu[node] = v; ++calls; });
  REQUIRE(calls < g.size() / 4);  // band of about 2 * 3 * 2 pi R ~ 400 nodes, not the grid
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double r = std::hypot(i + 0.5 - cx - 1.0, j + 0.5 - cy);
      REQUIRE(nu[g.index(i, j)] == Approx(contrast_viscosity(r - R, nu_a, nu_c)).margin(0.02 * (nu_c - nu_a)));
    }
}

TEST_CASE("Peskin 4-point kernel: unity, zero first moment, constant sum of squares", "[ib]") {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (int t = 0; t < 1000; ++t) {
    const double x = u(rng);
    const DeltaStencil1D s = delta_stencil(x, Delta::peskin4);
    double sum = 0, m1 = 0, sq = 0;
    for (int m = 0; m < 4; ++m) {
      const double r = x - (s.first + m + 0.5);
      REQUIRE(s.w[m] == Approx(peskin4_delta(r)).margin(1e-14));  // the closed-form kernel; rounding only
      sum += s.w[m];
      m1 += s.w[m] * r;
      sq += s.w[m] * s.w[m];
    }
    REQUIRE(sum == Approx(1.0).margin(1e-14));    // rounding only
    REQUIRE(m1 == Approx(0.0).margin(1e-13));     // exact first moment, rounding only
    REQUIRE(sq == Approx(0.375).margin(1e-14));   // Peskin's sum-of-squares condition 3/8
  }
}

TEST_CASE("Peskin kernel interpolates a linear field exactly and spreads conservatively (2D)", "[ib]") {
  const Grid g{32, 24, 1};
  std::vector<double> ux(g.size()), uy(g.size());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      ux[g.index(i, j)] = 0.3 + 0.01 * (i + 0.5) - 0.02 * (j + 0.5);
      uy[g.index(i, j)] = -0.1 + 0.005 * (j + 0.5);
    }
  const double* u[2] = {ux.data(), uy.data()};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> px(8.0, 24.0), py(6.0, 18.0);
  std::vector<double> X(2 * 50), U(2 * 50), F(2 * 50, 0.0);
  for (int c = 0; c < 50; ++c) {
    X[2 * c] = px(rng);
    X[2 * c + 1] = py(rng);
    F[2 * c] = std::sin(c);
    F[2 * c + 1] = std::cos(3.0 * c);
  }
  interpolate<2>(g, u, X.data(), 50, U.data(), Delta::peskin4);
  for (int c = 0; c < 50; ++c) {
    REQUIRE(U[2 * c] == Approx(0.3 + 0.01 * X[2 * c] - 0.02 * X[2 * c + 1]).margin(1e-14));  // rounding only
    REQUIRE(U[2 * c + 1] == Approx(-0.1 + 0.005 * X[2 * c + 1]).margin(1e-14));
  }
  std::vector<double> p0(g.size(), 0.0), p1(g.size(), 0.0);
  double* p[2] = {p0.data(), p1.data()};
  spread<2>(g, X.data(), F.data(), 50, p, Delta::peskin4);
  double Fx = 0, Fy = 0, sx = 0, sy = 0, torque_nodes = 0, torque_grid = 0;
  for (int c = 0; c < 50; ++c) {
    Fx += F[2 * c];
    Fy += F[2 * c + 1];
    torque_nodes += X[2 * c] * F[2 * c + 1] - X[2 * c + 1] * F[2 * c];
  }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t k = g.index(i, j);
      sx += p0[k];
      sy += p1[k];
      torque_grid += (i + 0.5) * p1[k] - (j + 0.5) * p0[k];
    }
  REQUIRE(sx == Approx(Fx).margin(1e-12));  // rounding only
  REQUIRE(sy == Approx(Fy).margin(1e-12));
  // zero first moment: spreading also conserves the torque (nodes away from the periodic seam)
  REQUIRE(torque_grid == Approx(torque_nodes).margin(1e-11));
}

TEST_CASE("viscosity contrast in 3D: sphere gives mu_c inside, mu_a outside", "[ib]") {
  const Grid g{32, 32, 24};
  const double R = 7.0, c[3] = {16.0, 16.0, 12.0};
  const int n = 2000;  // Fibonacci sphere: spacing sqrt(4 pi R^2 / n) = 0.55
  std::vector<double> X(3 * n), N(3 * n);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z), phi = golden * i;
    N[3 * i] = r * std::cos(phi);
    N[3 * i + 1] = r * std::sin(phi);
    N[3 * i + 2] = z;
    for (int d = 0; d < 3; ++d) X[3 * i + d] = c[d] + R * N[3 * i + d];
  }
  const double nu_a = 0.1, nu_c = 0.4;
  ViscosityContrast<3> vc(g, nu_a, nu_c);
  std::vector<double> nu(g.size(), -1.0);
  vc.update(X.data(), N.data(), n, [&](std::size_t node, double v) { nu[node] = v; });
  double worst = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const double r = std::sqrt(std::pow(i + 0.5 - c[0], 2) + std::pow(j + 0.5 - c[1], 2) + std::pow(k + 0.5 - c[2], 2));
        const double v = nu[g.index(i, j, k)];
        REQUIRE(v >= nu_a - 1e-15);  // every node set, within [mu_a, mu_c]
        REQUIRE(v <= nu_c + 1e-15);
        worst = std::max(worst, std::abs(v - contrast_viscosity(r - R, nu_a, nu_c)) / (nu_c - nu_a));
      }
  // nearest-node normal distance vs exact: node spacing 0.55 on R = 7 gives |d - (r - R)| ~ 0.03,
  // so |H error| <= 0.5 * 0.03 = 0.015; measured 0.0045
  INFO("worst relative viscosity error " << worst);
  REQUIRE(worst < 0.02);
}

TEST_CASE("narrow kernels roma3 and linear2: closed forms, unity, zero first moment", "[ib]") {
  // roma3 (Roma, Peskin and Berger 1999): 3 nodes, sum of squares 1/2 for every offset;
  // linear2 (hat): 2 nodes. Both interpolate linear fields exactly, like peskin4.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (Delta k : {Delta::roma3, Delta::linear2}) {
    for (int t = 0; t < 1000; ++t) {
      const double x = u(rng);
      const DeltaStencil1D s = delta_stencil(x, k);
      REQUIRE(s.width == delta_width(k));
      double sum = 0, m1 = 0, sq = 0;
      for (int m = 0; m < s.width; ++m) {
        const double r = x - (s.first + m + 0.5);
        REQUIRE(s.w[m] == Approx(k == Delta::roma3 ? roma3_delta(r) : linear2_delta(r)).margin(1e-14));
        sum += s.w[m];
        m1 += s.w[m] * r;
        sq += s.w[m] * s.w[m];
      }
      // the nodes outside the stencil carry no weight of the closed form
      REQUIRE((k == Delta::roma3 ? roma3_delta(x - (s.first - 1 + 0.5)) : linear2_delta(x - (s.first - 1 + 0.5))) ==
              Approx(0.0).margin(1e-14));
      REQUIRE(sum == Approx(1.0).margin(1e-14));  // rounding only
      REQUIRE(m1 == Approx(0.0).margin(1e-13));   // rounding only
      if (k == Delta::roma3) REQUIRE(sq == Approx(0.5).margin(1e-14));
    }
  }
}

TEST_CASE("a delta's name, width, support and stiffness bound are asked of it", "[ib]") {
  using capsule::choice_from_name;
  using capsule::choice_name;
  for (const auto& [delta, name] : delta_names) {
    CHECK(choice_name(delta) == name);
    CHECK(choice_from_name<Delta>(name) == delta);
    CHECK(delta_support_nodes(delta, 3) == delta_width(delta) * delta_width(delta) * delta_width(delta));
  }
  CHECK(choice_from_name<Delta>("roma3") == Delta::roma3);
  CHECK(choice_from_name<Delta>("keys4") == Delta::keys4);
  CHECK_FALSE(choice_from_name<Delta>("gauss"));  // no silent fallback
  CHECK_THROWS_WITH(capsule::choice_from_name_or_throw<Delta>("gauss", "IB delta"),
                    Catch::Contains("allowed: peskin4, roma3, linear2, cosine, keys4"));
  CHECK(delta_support_nodes(Delta::linear2, 3) == 8);
  CHECK(delta_support_nodes(Delta::roma3, 3) == 27);
  CHECK(delta_support_nodes(Delta::peskin4, 2) == 16);
  CHECK(maxwell_stiffness_bound(Delta::peskin4) == 0.4);
  CHECK(maxwell_stiffness_bound(Delta::roma3) == 0.15);
}

TEST_CASE("keys4: closed form, unity, zero first and second moments", "[ib]") {
  // Keys' cubic convolution (a = -1/2) interpolates quadratics exactly: its second moment
  // vanishes for every offset, where a positive kernel's cannot (peskin4 about 1/2, roma3 1/3).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (int t = 0; t < 1000; ++t) {
    const double x = u(rng);
    const DeltaStencil1D s = delta_stencil(x, Delta::keys4);
    REQUIRE(s.width == 4);
    double sum = 0, m1 = 0, m2 = 0;
    for (int m = 0; m < s.width; ++m) {
      const double r = x - (s.first + m + 0.5);
      REQUIRE(s.w[m] == Approx(keys4_delta(r)).margin(1e-14));
      sum += s.w[m];
      m1 += s.w[m] * r;
      m2 += s.w[m] * r * r;
    }
    REQUIRE(keys4_delta(x - (s.first - 1 + 0.5)) == Approx(0.0).margin(1e-14));
    REQUIRE(keys4_delta(x - (s.first + 4 + 0.5)) == Approx(0.0).margin(1e-14));
    REQUIRE(sum == Approx(1.0).margin(1e-13));  // rounding only (offsets up to 50)
    REQUIRE(m1 == Approx(0.0).margin(1e-12));
    REQUIRE(m2 == Approx(0.0).margin(1e-11));
  }
  // the positive kernels' second moments do not vanish (they vary with the offset)
  for (Delta k : {Delta::peskin4, Delta::roma3}) {
    const double x = 3.3;
    const DeltaStencil1D s = delta_stencil(x, k);
    double m2 = 0;
    for (int m = 0; m < s.width; ++m) m2 += s.w[m] * (x - (s.first + m + 0.5)) * (x - (s.first + m + 0.5));
    CHECK(m2 > 0.25);
  }
}

TEST_CASE("every kernel interpolates a linear field exactly and spreads adjointly in 3D", "[ib]") {
  const Grid g{16, 14, 12};
  std::vector<double> ux(g.size()), uy(g.size()), uz(g.size());
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t n = g.index(i, j, k);
        ux[n] = 0.2 + 0.01 * (j + 0.5);  // a shear flow
        uy[n] = -0.03 * (k + 0.5);
        uz[n] = 0.005 * (i + 0.5);
      }
  const double* u[3] = {ux.data(), uy.data(), uz.data()};
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> p(4.0, 10.0);
  const std::size_t n = 20;
  std::vector<double> X(3 * n), U(3 * n), F(3 * n);
  for (std::size_t c = 0; c < 3 * n; ++c) X[c] = p(rng), F[c] = std::sin(double(c));
  for (Delta k : {Delta::peskin4, Delta::roma3, Delta::linear2, Delta::keys4}) {
    interpolate<3>(g, u, X.data(), n, U.data(), k);
    for (std::size_t c = 0; c < n; ++c) {
      REQUIRE(U[3 * c] == Approx(0.2 + 0.01 * X[3 * c + 1]).margin(1e-14));  // rounding only
      REQUIRE(U[3 * c + 1] == Approx(-0.03 * X[3 * c + 2]).margin(1e-14));
      REQUIRE(U[3 * c + 2] == Approx(0.005 * X[3 * c]).margin(1e-14));
    }
    std::vector<double> p0(g.size()), p1(g.size()), p2(g.size());
    double* q[3] = {p0.data(), p1.data(), p2.data()};
    spread<3>(g, X.data(), F.data(), n, q, k);
    double lhs = 0, rhs = 0;
    for (std::size_t i = 0; i < g.size(); ++i) lhs += p0[i] * ux[i] + p1[i] * uy[i] + p2[i] * uz[i];
    for (std::size_t c = 0; c < 3 * n; ++c) rhs += F[c] * U[c];
    REQUIRE(lhs == Approx(rhs).margin(1e-12));  // adjoint: the same weights both ways
    clear_support<3>(g, X.data(), n, q, k);      // undoes exactly the nodes spread() touched
    for (std::size_t i = 0; i < g.size(); ++i) REQUIRE((p0[i] == 0.0 && p1[i] == 0.0 && p2[i] == 0.0));
  }
}

TEST_CASE("the spreading box spreads as spread<3> and clears exactly what it wrote, across the periodic seams", "[ib]") {
  // Nodes placed across the periodic seams in x and z and near a wall in y: the box must wrap
  // in x and z and clip in y. The force field is first filled with a marker everywhere, then
  // cleared; the spreading is compared with spread<3> bitwise (the same code, the same order).
  const Grid g{16, 10, 14};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> around(-1.2, 1.2), y(0.5, 4.0);
  const std::size_t n = 30;
  std::vector<double> X(3 * n), F(3 * n);
  for (std::size_t c = 0; c < n; ++c) {
    X[3 * c] = around(rng);           // both sides of x = 0
    X[3 * c + 1] = y(rng);            // near the wall y = 0: part of each stencil is dropped
    X[3 * c + 2] = 14.0 + around(rng);  // both sides of z = nz
    for (int d = 0; d < 3; ++d) F[3 * c + d] = std::cos(double(3 * c + d));
  }
  for (Delta k : {Delta::peskin4, Delta::roma3, Delta::linear2, Delta::keys4}) {
    std::vector<double> a0(g.size(), 7.0), a1(g.size(), 7.0), a2(g.size(), 7.0);
    std::vector<double> b0(g.size()), b1(g.size()), b2(g.size());
    double* p[3] = {a0.data(), a1.data(), a2.data()};
    double* q[3] = {b0.data(), b1.data(), b2.data()};
    SpreadingBox box;
    box.clear_last(g, p);  // before any spreading: the whole field
    for (std::size_t i = 0; i < g.size(); ++i) REQUIRE((a0[i] == 0.0 && a1[i] == 0.0 && a2[i] == 0.0));
    box.spread(g, X.data(), F.data(), n, p, k);
    spread<3>(g, X.data(), F.data(), n, q, k);
    REQUIRE(a0 == b0);
    REQUIRE(a1 == b1);
    REQUIRE(a2 == b2);
    // Clearing zeroes every written node and is a box, not the whole field.
    box.clear_last(g, p);
    for (std::size_t i = 0; i < g.size(); ++i) REQUIRE((a0[i] == 0.0 && a1[i] == 0.0 && a2[i] == 0.0));
    std::fill(a0.begin(), a0.end(), 7.0);
    box.clear_last(g, p);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (b0[i] != 0.0 || b1[i] != 0.0) REQUIRE(a0[i] == 0.0);  // written nodes are cleared
      kept += a0[i] == 7.0;
    }
    REQUIRE(kept > 0);  // and the clearing is a box, not the whole field
    box.forget();
    box.clear_last(g, p);
    for (std::size_t i = 0; i < g.size(); ++i) REQUIRE(a0[i] == 0.0);  // after forget(): everything
  }
}

TEST_CASE("the spreading box clears the whole field when the stencils span the periodic z axis", "[ib]") {
  // A box wider than the lattice in z would wrap onto itself: no box, the next clearing takes
  // everything. The box is the nodes' bounding box widened by 3 (support_rows): z 0.7 alone gives
  // layers -3..3 (7 <= nz = 10), with z 5.9 as well -3..8 (12 > 10).
  const Grid g{8, 8, 10};
  std::vector<double> X{4.0, 4.0, 0.7, 4.0, 4.0, 5.9}, F{1.0, 2.0, 3.0, -1.0, 0.5, 0.25};
  std::vector<double> a0(g.size(), 5.0), a1(g.size(), 5.0), a2(g.size(), 5.0);
  double* p[3] = {a0.data(), a1.data(), a2.data()};
  SpreadingBox box;
  box.spread(g, X.data(), F.data(), 1, p, Delta::peskin4);  // one node: a box
  box.clear_last(g, p);
  REQUIRE(a0[g.index(0, 0, 3)] == 5.0);  // far from the node in x and y: outside the box
  box.spread(g, X.data(), F.data(), 2, p, Delta::peskin4);  // a box 12 layers tall
  box.clear_last(g, p);
  for (std::size_t i = 0; i < g.size(); ++i) REQUIRE((a0[i] == 0.0 && a1[i] == 0.0 && a2[i] == 0.0));
}

TEST_CASE("spreading by z-layer arcs is bitwise spread<3> for any partition and thread count", "[ib]") {
  // Random node sets (a cloud across the periodic seams in x and z, near a wall in y, and one
  // spread over the whole lattice), random forces, every kernel: the arcs of any partition of
  // the z axis, spread one after another, and the spreading box on 1, 2 and 3 threads (the
  // threaded path, above 2048 nodes), give the same bits as the serial spread<3>.
  const Grid g{24, 18, 20};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0), force(-1.0, 1.0);
  const std::size_t n = 3000;
  for (int cloud = 0; cloud < 2; ++cloud) {
    std::vector<double> X(3 * n), F(3 * n);
    for (std::size_t c = 0; c < n; ++c) {
      if (cloud == 0) {  // a ball of radius 4 about a corner of the periodic box, 2 from the wall y = 0
        X[3 * c] = 4.0 * (2.0 * unit(rng) - 1.0), X[3 * c + 1] = 2.0 + 4.0 * unit(rng), X[3 * c + 2] = 20.0 + 4.0 * (2.0 * unit(rng) - 1.0);
      } else {  // anywhere: the stencils span z, so the box is the whole lattice
        X[3 * c] = g.nx * unit(rng), X[3 * c + 1] = g.ny * unit(rng), X[3 * c + 2] = g.nz * unit(rng);
      }
      for (int d = 0; d < 3; ++d) F[3 * c + d] = force(rng);
    }
    for (Delta k : {Delta::peskin4, Delta::cosine, Delta::roma3, Delta::linear2}) {
      INFO("cloud " << cloud << ", kernel " << static_cast<int>(k));
      std::vector<double> s0(g.size()), s1(g.size()), s2(g.size());
      double* serial[3] = {s0.data(), s1.data(), s2.data()};
      spread<3>(g, X.data(), F.data(), n, serial, k);
      // Partitions of the periodic z axis into arcs, uneven and across the seam.
      for (const std::vector<int>& cuts : {std::vector<int>{0, 20}, std::vector<int>{-3, 5, 6, 17}, std::vector<int>{13, 14, 30, 33}}) {
        std::vector<double> a0(g.size()), a1(g.size()), a2(g.size());
        double* p[3] = {a0.data(), a1.data(), a2.data()};
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
          spread_in_layers(g, X.data(), F.data(), n, p, k, LayerArc{cuts[i], cuts[i + 1] - cuts[i]});
        if (cuts.back() - cuts.front() < g.nz)  // the rest of the axis
          spread_in_layers(g, X.data(), F.data(), n, p, k, LayerArc{cuts.back(), g.nz - (cuts.back() - cuts.front())});
        REQUIRE(a0 == s0);
        REQUIRE(a1 == s1);
        REQUIRE(a2 == s2);
      }
      for (int threads : {1, 2, 3}) {
        INFO(threads << " threads");
        omp_set_num_threads(threads);
        std::vector<double> a0(g.size(), 7.0), a1(g.size(), 7.0), a2(g.size(), 7.0);
        double* p[3] = {a0.data(), a1.data(), a2.data()};
        SpreadingBox box;
        box.clear_last_and_spread(g, X.data(), F.data(), n, p, k);  // clears everything first
        REQUIRE(a0 == s0);
        REQUIRE(a1 == s1);
        REQUIRE(a2 == s2);
        box.clear_last_and_spread(g, X.data(), F.data(), n, p, k);  // clears its own box
        REQUIRE(a0 == s0);
        REQUIRE(a1 == s1);
        REQUIRE(a2 == s2);
        box.clear_last(g, p);
        for (std::size_t i = 0; i < g.size(); ++i) REQUIRE((a0[i] == 0.0 && a1[i] == 0.0 && a2[i] == 0.0));
        box.spread(g, X.data(), F.data(), n, p, k);
        REQUIRE(a0 == s0);
        REQUIRE(a1 == s1);
        REQUIRE(a2 == s2);
      }
      omp_set_num_threads(1);
    }
  }
}

TEST_CASE("the threaded spreading box clears the last box wherever the membrane moved to", "[ib]") {
  // The arcs follow the new box; the old box must still be cleared in full, also where it lies
  // outside the new one (the last thread's arc holds the layers outside the box).
  const Grid g{16, 16, 30};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = 2500;
  auto cloud = [&](double z) {
    std::vector<double> X(3 * n);
    for (std::size_t c = 0; c < n; ++c) X[3 * c] = 8 + 3 * unit(rng), X[3 * c + 1] = 8 + 3 * unit(rng), X[3 * c + 2] = z + 3 * unit(rng);
    return X;
  };
  const std::vector<double> F(3 * n, 0.5), here = cloud(2.0), there = cloud(17.0);
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    std::vector<double> a0(g.size()), a1(g.size()), a2(g.size()), s0(g.size()), s1(g.size()), s2(g.size());
    double* p[3] = {a0.data(), a1.data(), a2.data()};
    double* serial[3] = {s0.data(), s1.data(), s2.data()};
    SpreadingBox box;
    box.clear_last_and_spread(g, here.data(), F.data(), n, p, Delta::peskin4);
    box.clear_last_and_spread(g, there.data(), F.data(), n, p, Delta::peskin4);
    spread<3>(g, there.data(), F.data(), n, serial, Delta::peskin4);
    REQUIRE(a0 == s0);
    REQUIRE(a1 == s1);
    REQUIRE(a2 == s2);
  }
  omp_set_num_threads(1);
}

TEST_CASE("membrane position update: forward Euler first order, Adams-Bashforth second order", "[ib]") {
  // dX/dt = U(X) = omega x X (rigid rotation, omega = 1 about z): exact X(t) = R(t) X(0). Each
  // update reads U at the node's current position, as the IB step does (membrane_update.hpp).
  // Integrate to t = 1 with dt = 0.1, 0.05, 0.025: halving dt halves the Euler error and
  // quarters the Adams-Bashforth error (order from the last two levels within 0.1 of 1 and 2).
  auto error = [](bool ab2, double dt) {
    std::vector<double> X{1.0, 0.0, 0.0, 0.0, 0.5, 0.25}, U(6), U_previous;
    const int steps = static_cast<int>(std::lround(1.0 / dt));
    for (int s = 0; s < steps; ++s) {
      for (int c = 0; c < 2; ++c) {
        U[3 * c] = -X[3 * c + 1];
        U[3 * c + 1] = X[3 * c];
        U[3 * c + 2] = 0.0;
      }
      if (ab2) advance_adams_bashforth2<3>(X.data(), U.data(), U_previous, 2, dt);
      else advance<3>(X.data(), U.data(), 2, dt);
    }
    const double c = std::cos(1.0), s = std::sin(1.0);
    const double exact[6] = {c, s, 0.0, -0.5 * s, 0.5 * c, 0.25};
    double e = 0;
    for (int i = 0; i < 6; ++i) e = std::max(e, std::abs(X[i] - exact[i]));
    return e;
  };
  for (const bool ab2 : {false, true}) {
    const double e1 = error(ab2, 0.1), e2 = error(ab2, 0.05), e3 = error(ab2, 0.025);
    const double p12 = std::log2(e1 / e2), p23 = std::log2(e2 / e3);
    INFO((ab2 ? "adams_bashforth2" : "euler") << ": errors " << e1 << ", " << e2 << ", " << e3 << "; orders " << p12
                                               << ", " << p23);
    CHECK(p23 == Approx(ab2 ? 2.0 : 1.0).margin(0.1));
    CHECK(p12 < p23 + 0.3);  // the order settles as dt falls
  }
  CHECK(error(true, 0.025) < 0.05 * error(false, 0.025));
  CHECK(capsule::choice_from_name<MembraneUpdate>("previous_velocity") == MembraneUpdate::previous_velocity);
  CHECK_FALSE(capsule::choice_from_name<MembraneUpdate>("rk4"));
}

TEST_CASE("first_marker_outside finds the first marker that is NaN, beyond a wall or absurdly far", "[ib]") {
  const capsule::ib::Grid g{8, 6, 4};
  std::vector<double> X{1.0, 2.0, 3.0, 7.9, 5.9, 0.1, -3.0, 0.0, 10.0};  // three markers inside (x, z periodic)
  CHECK(capsule::ib::first_marker_outside<3>(g, X.data(), 3) == -1);
  X[4] = 6.2;  // marker 1 past the wall y = ny
  CHECK(capsule::ib::first_marker_outside<3>(g, X.data(), 3) == 1);
  X[4] = 5.0;
  X[6] = std::nan("");  // marker 2 NaN
  CHECK(capsule::ib::first_marker_outside<3>(g, X.data(), 3) == 2);
  X[6] = 2e6;  // or a million lattice spacings along x
  CHECK(capsule::ib::first_marker_outside<3>(g, X.data(), 3) == 2);
  const std::vector<double> Y{1.0, 2.0, 1.0, -0.5};  // 2D: marker 1 below the wall y = 0
  CHECK(capsule::ib::first_marker_outside<2>(g, Y.data(), 2) == 1);
}
