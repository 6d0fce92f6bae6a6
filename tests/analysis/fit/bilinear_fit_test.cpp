// Bilinear model (95)-(96): the Ceres fit must equal the closed-form least-squares
// solution and the textbook intervals; the artificial viscosity maps (97)-(98).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "analysis/fit/artificial_viscosity.hpp"
#include "analysis/fit/bilinear_fit.hpp"
#include "analysis/fit/fit_statistics.hpp"

using namespace capsule::analysis;

namespace {
struct Grid {
  std::vector<double> eta, V, y;
};
// An (eta, V) grid like the Table 2 ensembles, k tau = a eta + b V + c + noise.
Grid make_grid(double a, double b, double c, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  Grid g;
  for (double eta : {0.0, 1.0, 2.0, 5.0, 10.0})
    for (double V : {0.2, 1.0, 2.0, 5.0}) {
      g.eta.push_back(eta);
      g.V.push_back(V);
      g.y.push_back(a * eta + b * V + c + noise(rng));
    }
  return g;
}
}  // namespace

TEST_CASE("Student's t quantiles match published tables", "[analysis]") {
  // Reference values: two-sided 95 % t quantiles (e.g. NIST/SEMATECH handbook table), 12 digits.
  CHECK(student_t_975(1) == Approx(12.7062047362).epsilon(1e-10));
  CHECK(student_t_975(10) == Approx(2.22813885196).epsilon(1e-10));
  CHECK(student_t_975(17) == Approx(2.10981557783).epsilon(1e-10));
  CHECK(std::isnan(student_t_975(0)));
}

TEST_CASE("Bilinear Ceres fit equals the closed-form least-squares solution", "[analysis]") {
  // The dissertation's Table 2 coefficients for k tau_s (Ca = 0.05, E_b = 0) as truth.
  const Grid g = make_grid(0.0208, 0.0590, 0.4158, 0.02, 7u);
  const FitResult fit = fit_bilinear(g.eta, g.V, g.y);
  REQUIRE(fit.ok);
  CHECK(fit.converged);

  const Eigen::Index n = static_cast<Eigen::Index>(g.y.size());
  Eigen::MatrixXd X(n, 3);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    X(i, 0) = g.eta[i];
    X(i, 1) = g.V[i];
    X(i, 2) = 1.0;
    y(i) = g.y[i];
  }
  const Eigen::VectorXd beta = X.colPivHouseholderQr().solve(y);
  const Eigen::VectorXd r = y - X * beta;
  const double s2 = r.squaredNorm() / static_cast<double>(n - 3);
  const Eigen::Matrix3d cov = s2 * (X.transpose() * X).inverse();
  const double t = student_t_975(static_cast<std::size_t>(n - 3));
  const double ss_tot = (y.array() - y.mean()).square().sum();

  // 1e-8: the brief's bound; the problem is linear and well conditioned (cond(X) ~ 30),
  // so both solutions agree to round-off (~1e-13) and 1e-8 leaves room for Ceres' stopping.
  for (int i = 0; i < 3; ++i) {
    INFO("coefficient " << i);
    CHECK(std::abs(fit.parameters[i].value - beta(i)) < 1e-8);
    CHECK(std::abs(fit.parameters[i].std_error - std::sqrt(cov(i, i))) < 1e-8);
    CHECK(std::abs(fit.parameters[i].ci_low - (beta(i) - t * std::sqrt(cov(i, i)))) < 1e-8);
    CHECK(std::abs(fit.parameters[i].ci_high - (beta(i) + t * std::sqrt(cov(i, i)))) < 1e-8);
    for (int j = 0; j < 3; ++j) CHECK(std::abs(fit.covariance[i][j] - cov(i, j)) < 1e-8);
  }
  CHECK(std::abs(fit.reduced_chi_square - s2) < 1e-8);
  CHECK(std::abs(fit.r_squared - (1.0 - r.squaredNorm() / ss_tot)) < 1e-8);
  CHECK(fit.n_points == 20);
}

TEST_CASE("Bilinear intervals cover the truth in 90-99 % of 200 seeds", "[analysis]") {
  // Seeds 1..200; binomial s.d. at 95 % of 200 is 3.1, so [0.90, 0.99] is a > 2.5 s.d. band.
  const double truth[3] = {0.0534, 0.2711, 0.3986};  // Table 2, k tau_r, Ca = 0.05, E_b = 0
  int covered[3] = {0, 0, 0};
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const Grid g = make_grid(truth[0], truth[1], truth[2], 0.02, seed);
    const FitResult fit = fit_bilinear(g.eta, g.V, g.y);
    REQUIRE(fit.ok);
    for (int i = 0; i < 3; ++i)
      covered[i] += (fit.parameters[i].ci_low <= truth[i] && truth[i] <= fit.parameters[i].ci_high) ? 1 : 0;
  }
  for (int i = 0; i < 3; ++i) {
    INFO("coefficient " << i << " covered " << covered[i] << " / 200");
    CHECK(covered[i] >= 180);
    CHECK(covered[i] <= 198);
  }
}

TEST_CASE("Artificial viscosity maps (97)-(98) invert each other", "[analysis]") {
  const Grid g = make_grid(0.02, 0.06, 0.4, 0.001, 3u);
  const FitResult fit = fit_bilinear(g.eta, g.V, g.y);
  REQUIRE(fit.ok);
  const Ratio ab = ratio_a_over_b(fit), ba = ratio_b_over_a(fit);
  // Noise 0.001 on k tau ~ 0.4-1: a/b = 1/3 to within a few 1e-3.
  CHECK(ab.value == Approx(0.02 / 0.06).margin(0.01));
  CHECK(ab.value * ba.value == Approx(1.0).epsilon(1e-12));  // exact reciprocals
  CHECK(ab.std_error > 0.0);
  // (98) then (97): eta -> V* -> eta again.
  const double V = 0.2, eta = 4.0;
  const double V_star = artificial_V(ab.value, V, eta);
  CHECK(V_star == Approx(V + ab.value * eta).epsilon(1e-15));
  CHECK(artificial_eta(ba.value, V_star, V) == Approx(eta).epsilon(1e-12));
  // The artificial V* reproduces the modelled time: a eta + b V + c = b V* + c.
  const double a = fit.parameters[0].value, b = fit.parameters[1].value, c = fit.parameters[2].value;
  CHECK(a * eta + b * V + c == Approx(b * V_star + c).epsilon(1e-12));
}

TEST_CASE("Delta-method error of a/b matches a Monte Carlo over seeds", "[analysis]") {
  // 400 noisy grids (seeds 1..400): the spread of a/b must agree with the delta-method
  // standard error to within 20 % (the sampling error of a s.d. from 400 draws is ~4 %,
  // and the first-order delta method is good to a few % at a/b's ~10 % relative error).
  std::vector<double> ratios;
  double mean_se = 0.0;
  for (unsigned seed = 1; seed <= 400; ++seed) {
    const Grid g = make_grid(0.05, 0.25, 0.4, 0.02, seed);
    const FitResult fit = fit_bilinear(g.eta, g.V, g.y);
    REQUIRE(fit.ok);
    const Ratio r = ratio_a_over_b(fit);
    ratios.push_back(r.value);
    mean_se += r.std_error / 400.0;
  }
  double mean = 0.0;
  for (double r : ratios) mean += r / 400.0;
  double var = 0.0;
  for (double r : ratios) var += (r - mean) * (r - mean) / 399.0;
  CHECK(std::sqrt(var) == Approx(mean_se).epsilon(0.2));
}
