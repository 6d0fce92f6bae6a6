// The exact implicit Kelvin-Voigt step of the 2D membrane (resolution.kelvin_voigt_step =
// "exact_mobility"): the IB mobility of one step (solver/ib/mobility.hpp) against a real fluid
// step, the coupled viscous solve (Membrane::compute_forces_coupled) against the motion it
// produces, and members: eta = 200 stable and converged in the segment count, eta <= 12 as
// with the approximate step (measurements: docs/findings/kelvin_voigt_2d.md).
#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <omp.h>
#include <random>
#include <vector>

#include "solver/ib/interpolation.hpp"
#include "solver/ib/mobility.hpp"
#include "solver/lbm/fluid.hpp"
#include "solver/membrane2d/membrane.hpp"
#include "solver/membrane2d/shape.hpp"
#include "solver/run/simulation2d.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

constexpr ib::Delta kK = ib::Delta::peskin4;

// A fluid that is neither at rest nor uniform in density: Couette flow plus a few steps of a
// random force field.
void stir(lbm::Fluid<lbm::D2Q9>& fluid, std::mt19937& rng) {
  const double H = fluid.ny();
  fluid.initialise_velocity([&](double, double y, double) { return std::array<double, 3>{0.01 * (y / H - 0.5), 0, 0}; });
  std::uniform_real_distribution<double> f(-1e-3, 1e-3);
  for (int s = 0; s < 3; ++s) {
    for (std::size_t i = 0; i < fluid.size(); ++i) fluid.force(0)[i] = f(rng), fluid.force(1)[i] = f(rng);
    fluid.step();
  }
  fluid.clear_force();
}

// Nodes on a circle (counter-clockwise), radius r about (cx, cy), slightly wobbled.
std::vector<double> ring(std::size_t n, double r, double cx, double cy, double wobble) {
  std::vector<double> xy(2 * n);
  for (std::size_t c = 0; c < n; ++c) {
    const double t = 2.0 * std::numbers::pi * c / n, rr = r * (1.0 + wobble * std::cos(2.0 * t));
    xy[2 * c] = cx + rr * std::cos(t);
    xy[2 * c + 1] = cy + rr * std::sin(t);
  }
  return xy;
}

// Steps the fluid with node forces F spread from X and returns the interpolated node velocities.
std::vector<double> fluid_step(lbm::Fluid<lbm::D2Q9>& fluid, const ib::Grid& grid, const std::vector<double>& X,
                               const std::vector<double>& F) {
  const std::size_t n = X.size() / 2;
  double* p[2] = {fluid.force(0), fluid.force(1)};
  fluid.clear_force();
  ib::spread<2>(grid, X.data(), F.data(), n, p, kK);
  fluid.step();
  const double* u[2] = {fluid.velocity(0), fluid.velocity(1)};
  std::vector<double> U(2 * n);
  ib::interpolate<2>(grid, u, X.data(), n, U.data(), kK);
  return U;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST_CASE("the step's IB mobility gives the node velocities a real fluid step gives: U = U_free + M F", "[capsule2d][kelvin_voigt]") {
  const int nx = 48, ny = 40;
  lbm::Fluid<lbm::D2Q9> fluid(nx, ny, 1, 1.0 / 6.0);
  const ib::Grid grid{nx, ny, 1};
  std::mt19937 rng(7);
  stir(fluid, rng);
  // A ring that wraps around the periodic x edge and whose lowest nodes' kernels reach past the
  // wall at y = 0 (rows dropped), 0.6 lattice units between nodes: every kind of overlap.
  const std::size_t n = 50;
  const auto X = ring(n, 5.0, 1.5, 5.8, 0.1);
  std::vector<double> F(2 * n);
  std::uniform_real_distribution<double> f(-1e-3, 1e-3);
  for (double& x : F) x = f(rng);

  ib::StepMobility2D mob;
  mob.assemble(grid, X.data(), n, kK, [&](std::size_t node) { return fluid.moments(node); });
  const auto predicted = mob.predict(F.data());
  const auto U = fluid_step(fluid, grid, X, F);
  std::vector<double> err(2 * n);
  for (std::size_t i = 0; i < 2 * n; ++i) err[i] = U[i] - predicted[i];
  INFO("max |U| " << max_abs(U) << ", max |U - (U_free + M F)| " << max_abs(err));
  CHECK(max_abs(U) > 1e-4);
  CHECK(max_abs(err) < 1e-13);  // the split is exact: rounding only

  // M: symmetric, self-mobility (3/8)^2 / (2 rho) away from the wall, positive semi-definite,
  // and it couples only nodes less than 4 lattice units apart along both axes.
  const Eigen::MatrixXd M(mob.matrix());
  CHECK((M - M.transpose()).norm() == 0.0);
  const std::size_t top = n / 4;  // y = 5.8 + 5.5: full support
  CHECK(M(top, top) == Approx(0.5 * 9.0 / 64.0).epsilon(2e-3));  // rho differs from 1 by ~1e-3
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M);
  CHECK(eig.eigenvalues().minCoeff() > -1e-15);
  CHECK(M(0, n / 2) == 0.0);  // opposite ends of the ring, 10 apart
}

TEST_CASE("exact Kelvin-Voigt: the viscous tension is mu_s times the stretch rate of the motion the step really gives",
          "[capsule2d][kelvin_voigt]") {
  const int nx = 64, ny = 48;
  lbm::Fluid<lbm::D2Q9> fluid(nx, ny, 1, 1.0 / 6.0);
  const ib::Grid grid{nx, ny, 1};
  std::mt19937 rng(11);
  stir(fluid, rng);
  const std::size_t n = 90;
  const double mu_s = 200.0;  // eta = 200 at a = 6 with nu = 1/6
  membrane2d::Membrane membrane(ring(n, 6.0, 32.0, 24.0, 0.0), {1e-3, 1e-5, mu_s});
  membrane.positions() = ring(n, 6.0, 32.0, 24.0, 0.15);  // deformed: Hooke and bending forces
  ib::StepMobility2D mob;
  mob.assemble(grid, membrane.positions().data(), n, kK, [&](std::size_t node) { return fluid.moments(node); });
  membrane.compute_forces_coupled(mob.free_velocity(), mob.matrix());
  const auto X = membrane.positions();
  const auto U = fluid_step(fluid, grid, X, membrane.forces());
  const auto& tau_v = membrane.viscous_tension();
  double worst = 0, scale = 0, free_rate = 0;  // free_rate: of U_free alone, for the message
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double dx = X[2 * j] - X[2 * i], dy = X[2 * j + 1] - X[2 * i + 1], l = std::hypot(dx, dy);
    const double rate = (dx * (U[2 * j] - U[2 * i]) + dy * (U[2 * j + 1] - U[2 * i + 1])) / (l * l);
    const double Uf[2] = {mob.free_velocity()[2 * j] - mob.free_velocity()[2 * i],
                          mob.free_velocity()[2 * j + 1] - mob.free_velocity()[2 * i + 1]};
    free_rate = std::max(free_rate, std::abs(dx * Uf[0] + dy * Uf[1]) / (l * l));
    worst = std::max(worst, std::abs(tau_v[i] - mu_s * rate));
    scale = std::max(scale, std::abs(tau_v[i]));
  }
  INFO("max |tau_v| " << scale << ", max |tau_v - mu_s t.dU/l| " << worst << ", free stretch rate " << free_rate);
  CHECK(scale > 1e-4);
  CHECK(worst < 1e-10 * scale);  // measured 4e-16 against 1e-2: exact up to rounding
}

namespace {

nlohmann::json viscous_scene(double a, double eta, int segments, const std::string& step, double kt) {
  return {{"dim", 2},
          {"shape", "circle"},
          {"Ca", 0.04},
          {"E_b", 0.05},
          {"V", 1},
          {"eta", eta},
          {"resolution", {{"a", a}, {"segments", segments}, {"kelvin_voigt_step", step}}},
          {"protocol", {{"shear", {{"until", "time"}, {"kt", kt}}}, {"recover", {{"until", "time"}, {"kt", 0.5}}}}}};
}

struct ViscousRun {
  std::vector<double> D;  // D_xy at kt = 0.25, 0.5, ... kt_end
  std::string health;
};

ViscousRun run_viscous(const nlohmann::json& j, double kt_end) {
  omp_set_num_threads(1);
  Simulation2D sim(Scene::from_json(j, "test"));
  ViscousRun r;
  double next = 0.25;
  while (sim.kt() < kt_end - 1e-9) {
    sim.step(1.0);
    if (!sim.failure().empty()) {  // a blow-up stops the steps
      r.health = sim.failure();
      break;
    }
    if (sim.kt() >= next - 1e-9) {
      const auto row = sim.row();
      r.health = sim.health(row);
      if (!r.health.empty()) break;
      r.D.push_back(row.at("D_xy"));
      next += 0.25;
    }
  }
  return r;
}

}  // namespace

TEST_CASE("exact Kelvin-Voigt step: eta = 200 runs where the approximate step blows up, and converges with segments",
          "[capsule2d][kelvin_voigt]") {
  // a = 5 keeps it at CI size (kt 0.75 = 2400 steps, about a second a run).
  const double kt = 0.75;
  const auto approx = run_viscous(viscous_scene(5, 200, 140, "approximate_mobility", kt), kt);
  const auto n70 = run_viscous(viscous_scene(5, 200, 70, "exact_mobility", kt), kt);
  const auto n140 = run_viscous(viscous_scene(5, 200, 140, "exact_mobility", kt), kt);
  const auto eta0 = run_viscous(viscous_scene(5, 0, 140, "exact_mobility", kt), kt);
  INFO("approximate: '" << approx.health << "'; exact 70 segments: '" << n70.health << "', 140: '" << n140.health << "'");
  CHECK_FALSE(approx.health.empty());  // the approximate mobility's step is unstable here
  REQUIRE(n70.health.empty());
  REQUIRE(n140.health.empty());
  REQUIRE(n70.D.size() == 3);
  REQUIRE(n140.D.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    INFO("kt " << 0.25 * (k + 1) << ": D_xy 70 segments " << n70.D[k] << ", 140 " << n140.D[k] << ", eta 0 " << eta0.D[k]);
    INFO("kt " << 0.25 * (k + 1) << ": D_xy 70 segments " << n70.D[k] << ", 140 " << n140.D[k] << ", eta 0 " << eta0.D[k]);
    // the viscous membrane responds markedly slower than eta = 0
    CHECK(n140.D[k] < 0.9 * eta0.D[k]);
    // Segment convergence: halving the segments (0.22 -> 0.45 lattice units apart at a = 5) moves
    // D_xy by at most 0.09 % (measured: 0.0851 / 0.0850, 0.11881 / 0.11882, 0.13962 / 0.13960).
    // 0.5 %, the bar set for an unchanged member, is 5x that: it leaves room for rounding on
    // other platforms, and a viscous step that depended on the node spacing (the approximate one
    // assumes a self-mobility per node, which does) would miss it.
    CHECK(std::abs(n70.D[k] / n140.D[k] - 1.0) < 0.005);
  }
}

TEST_CASE("exact Kelvin-Voigt step: eta <= 12 members move by less than 0.5 % from the approximate step",
          "[capsule2d][kelvin_voigt]") {
  const double kt = 0.75;
  for (const double eta : {2.0, 12.0}) {
    const auto a = run_viscous(viscous_scene(5, eta, 140, "approximate_mobility", kt), kt);
    const auto x = run_viscous(viscous_scene(5, eta, 140, "exact_mobility", kt), kt);
    REQUIRE(a.health.empty());
    REQUIRE(x.health.empty());
    REQUIRE(a.D.size() == x.D.size());
    // measured: at most 1.1e-4 relative (eta = 12, kt 0.75: 0.194622 / 0.194643)
    for (std::size_t k = 0; k < a.D.size(); ++k) {
      INFO("eta " << eta << ", kt " << 0.25 * (k + 1) << ": approximate " << a.D[k] << ", exact " << x.D[k]);
      CHECK(std::abs(x.D[k] / a.D[k] - 1.0) < 0.005);
    }
  }
}
