// The MRT matrices built from the velocity polynomials (docs/guide/model.md "Fluid"): orthogonal rows,
// M M^-1 = I, D2Q9 reproduces (6), and the equilibrium moments conserve rho and j.
#include <Eigen/Dense>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/lbm/collision.hpp"
#include "solver/lbm/equilibrium.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/moment_basis.hpp"

using namespace capsule::lbm;

namespace {

template <class L>
Eigen::MatrixXd moment_matrix() {
  Eigen::MatrixXd m(L::Q, L::Q);
  for (int k = 0; k < L::Q; ++k)
    for (int i = 0; i < L::Q; ++i) m(k, i) = MomentBasis<L>::M[k][i];
  return m;
}

// M^-1 as the collision kernel uses it: M^T diag(1/|M_k|^2).
template <class L>
Eigen::MatrixXd inverse_from_norms() {
  Eigen::MatrixXd m = moment_matrix<L>().transpose();
  for (int k = 0; k < L::Q; ++k) m.col(k) /= double(MomentBasis<L>::norm2[k]);
  return m;
}

template <class L>
void check_basis() {
  using B = MomentBasis<L>;
  const Eigen::MatrixXd M = moment_matrix<L>();
  // Integer entries: the Gram matrix must be exactly diagonal.
  const Eigen::MatrixXd gram = M * M.transpose();
  for (int a = 0; a < L::Q; ++a)
    for (int b = 0; b < L::Q; ++b)
      if (a != b) REQUIRE(gram(a, b) == 0.0);
  // M M^-1 = I with the inverse the kernel uses, and against Eigen's LU inverse.
  // 1e-14: entries are O(1) to O(100) rationals, so only round-off is allowed.
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(L::Q, L::Q);
  REQUIRE((M * inverse_from_norms<L>() - I).cwiseAbs().maxCoeff() < 1e-14);
  REQUIRE((inverse_from_norms<L>() - M.inverse()).cwiseAbs().maxCoeff() < 1e-14);
  // Every moment is even or odd under c -> -c (the kernel relies on it).
  for (int k = 0; k < L::Q; ++k) REQUIRE(std::abs(B::parity[k]) == 1);
  // Rows 0 and the momentum rows are 1 and c_a.
  for (int i = 0; i < L::Q; ++i) REQUIRE(B::M[0][i] == 1);
  int momentum_rows = 0;
  for (int k = 0; k < L::Q; ++k)
    if (MomentBasis<L>::momentum_component(k) >= 0) ++momentum_rows;
  REQUIRE(momentum_rows == L::D);
  // Weights sum to one and are isotropic to second order (sum w c_a c_b = delta_ab/3).
  int wsum = 0;
  for (int i = 0; i < L::Q; ++i) wsum += L::weight_numerator[i];
  REQUIRE(wsum == L::weight_denominator);
  for (int a = 0; a < L::D; ++a)
    for (int b = 0; b < L::D; ++b) {
      int s = 0;
      for (int i = 0; i < L::Q; ++i) s += L::weight_numerator[i] * L::c[i][a] * L::c[i][b];
      REQUIRE(3 * s == (a == b ? L::weight_denominator : 0));
    }
}

template <class L>
void check_equilibrium_moments() {
  using B = MomentBasis<L>;
  const Eigen::MatrixXd M = moment_matrix<L>();
  const std::array<std::array<double, 3>, 3> velocities{{{0.05, -0.02, 0.01}, {-0.1, 0.07, -0.03}, {0.0, 0.0, 0.0}}};
  for (double rho : {1.0, 0.97, 1.04}) {
    for (const auto& u : velocities) {
      double feq[L::Q];
      equilibrium<L>(rho, u, feq);
      Eigen::VectorXd f(L::Q);
      for (int i = 0; i < L::Q; ++i) f(i) = feq[i];
      const Eigen::VectorXd m = M * f;
      // Conservation: density and momentum of f_eq are rho and rho u (1e-15: round-off of O(1) sums).
      REQUIRE(std::abs(m(0) - rho) < 1e-15);
      for (int k = 0; k < L::Q; ++k) {
        const int a = MomentBasis<L>::momentum_component(k);
        if (a >= 0) REQUIRE(std::abs(m(k) - rho * u[a]) < 1e-15);
      }
      // The kernel's integer equilibrium coefficients equal M f_eq (5).
      double j[3] = {rho * u[0], rho * u[1], L::D == 3 ? rho * u[2] : 0.0};
      for (int k = 0; k < L::Q; ++k) {
        double meq = B::eq_A[k] * rho;
        for (int a = 0; a < L::D; ++a) meq += B::eq_B[k][a] * j[a];
        for (int a = 0; a < L::D; ++a)
          for (int b = 0; b < L::D; ++b) meq += B::eq_C[k][a][b] * j[a] * j[b] / (2.0 * rho);
        meq /= L::weight_denominator;
        // 1e-13: m_k reaches ~30 (row e), so a few ulps of 30.
        REQUIRE(std::abs(meq - m(k)) < 1e-13);
      }
    }
  }
}

// Collision without force conserves rho and j; with force it adds exactly F to j.
template <class L>
void check_collision_conservation() {
  const std::array<double, 3> u{0.04, -0.03, 0.02};
  double f[L::Q];
  equilibrium<L>(1.02, u, f);
  // Perturb away from equilibrium by a pattern with zero mass and momentum change.
  for (int i = 1; i < L::Q; ++i) f[i] += 1e-3 * (i % 3 - 1) * (L::weight_numerator[i]);
  double rho0 = 0.0, j0[3] = {0, 0, 0};
  for (int i = 0; i < L::Q; ++i) {
    rho0 += f[i];
    for (int a = 0; a < 3; ++a) j0[a] += f[i] * L::c[i][a];
  }
  const double force[3] = {1e-4, -2e-4, L::D == 3 ? 3e-4 : 0.0};
  double rho, vel[3];
  Collision<L>::collide(f, force, 1.3, rho, vel);
  double rho1 = 0.0, j1[3] = {0, 0, 0};
  for (int i = 0; i < L::Q; ++i) {
    rho1 += f[i];
    for (int a = 0; a < 3; ++a) j1[a] += f[i] * L::c[i][a];
  }
  // 1e-15: round-off of O(1) sums.
  REQUIRE(std::abs(rho - rho0) < 1e-15);
  REQUIRE(std::abs(rho1 - rho0) < 1e-15);
  for (int a = 0; a < L::D; ++a) {
    REQUIRE(std::abs(j1[a] - (j0[a] + force[a])) < 1e-15);               // (23): j'' = j + F
    REQUIRE(std::abs(vel[a] - (j0[a] + 0.5 * force[a]) / rho0) < 1e-15);  // (22): u = j'/rho
  }
}

}  // namespace

TEST_CASE("MRT matrix from the velocity polynomials: orthogonal, invertible (D2Q9, D3Q19)", "[lbm]") {
  check_basis<D2Q9>();
  check_basis<D3Q19>();
}

TEST_CASE("D2Q9 moment matrix equals (6) of the dissertation", "[lbm]") {
  const int m6[9][9] = {{1, 1, 1, 1, 1, 1, 1, 1, 1},     {-4, -1, -1, -1, -1, 2, 2, 2, 2},
                        {4, -2, -2, -2, -2, 1, 1, 1, 1},  {0, 1, 0, -1, 0, 1, -1, -1, 1},
                        {0, -2, 0, 2, 0, 1, -1, -1, 1},   {0, 0, 1, 0, -1, 1, 1, -1, -1},
                        {0, 0, -2, 0, 2, 1, 1, -1, -1},   {0, 1, -1, 1, -1, 0, 0, 0, 0},
                        {0, 0, 0, 0, 0, 1, -1, 1, -1}};
  for (int k = 0; k < 9; ++k)
    for (int i = 0; i < 9; ++i) REQUIRE(MomentBasis<D2Q9>::M[k][i] == m6[k][i]);
}

TEST_CASE("D3Q19 moment matrix: the intact rows of (11) agree", "[lbm]") {
  // Rows of (11) that survived intact in the text: rho (all ones), eps, and the
  // stress pxy = cx cy; checked against the polynomials in the velocity order (4).
  using B = MomentBasis<D3Q19>;
  const int eps[19] = {12, -4, -4, -4, -4, -4, -4, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  const int pxy[19] = {0, 0, 0, 0, 0, 0, 0, 1, -1, -1, 1, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 19; ++i) {
    REQUIRE(B::M[0][i] == 1);
    REQUIRE(B::M[2][i] == eps[i]);
    REQUIRE(B::M[13][i] == pxy[i]);
  }
}

TEST_CASE("Equilibrium moments conserve density and momentum and equal M f_eq", "[lbm]") {
  check_equilibrium_moments<D2Q9>();
  check_equilibrium_moments<D3Q19>();
}

TEST_CASE("Collision conserves mass and adds the force to the momentum (22)-(23)", "[lbm]") {
  check_collision_conservation<D2Q9>();
  check_collision_conservation<D3Q19>();
}
