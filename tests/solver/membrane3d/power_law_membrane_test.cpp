// The power law taken into the membrane (elasticity.hpp PowerLawRelaxation): the surface shear
// rate (101) of a triangle from its own motion, and the standard linear solid's Maxwell element
// whose relaxation time follows the power-law surface viscosity (102).
#include <catch2/catch.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "solver/membrane3d/elasticity.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "solver/membrane3d/surface_shear_rate.hpp"
#include "tests/solver/membrane3d/single_triangle.hpp"

using namespace capsule::membrane3d;
using capsule::membrane3d::testing::single_triangle;

namespace {

// The reference triangle under the planar deformation gradient F (x, y in its plane), then
// turned rigidly by R: R changes the positions, not C.
Mesh deformed(const Mesh& ref, const Eigen::Matrix2d& F, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  Mesh m = ref;
  for (auto& x : m.x) {
    const Eigen::Vector2d p = F * Eigen::Vector2d(x.x(), x.y());
    x = R * Vec3(p.x(), p.y(), 0.0);
  }
  return m;
}

Eigen::Matrix2d simple_shear(double amount) { return (Eigen::Matrix2d() << 1.0, amount, 0.0, 1.0).finished(); }

const Constitutive kNeoHookean{ElasticLaw::neo_hookean, 1.0, 15.0};

}  // namespace

TEST_CASE("surface shear rate (101): zero for a rigid motion, the rate of a simple shear, of an area dilation", "[membrane3d]") {
  const Mat2 I = Mat2::Identity();
  CHECK(surface_shear_rate(I, I, 1.0) == 0.0);
  // Simple shear x += s t y from the reference: D = [[0, s/2], [s/2, 0]], sqrt(2 tr D^2) = s.
  // The backward difference over dt is second order about the midpoint: at t = 0 its error is
  // O((s dt)^2), 1e-8 here.
  const double s = 1e-3, dt = 0.1;
  const Eigen::Matrix2d F = simple_shear(s * dt);
  CHECK(surface_shear_rate(I, Mat2(F.transpose() * F), dt) == Approx(s).epsilon(1e-6));
  // Later in the same shear (strain 0.5): still s, since D does not depend on the strain.
  const Eigen::Matrix2d F0 = simple_shear(0.5), F1 = simple_shear(0.5 + s * dt);
  CHECK(surface_shear_rate(Mat2(F0.transpose() * F0), Mat2(F1.transpose() * F1), dt) == Approx(s).epsilon(1e-6));
  // Isotropic area dilation F = (1 + e t) I: D = e / (1 + e t) I, sqrt(2 tr D^2) = 2 e / (1 + e t).
  const double e = 2e-3, t = 50.0;
  const double l0 = 1.0 + e * t, l1 = 1.0 + e * (t + dt);
  CHECK(surface_shear_rate(Mat2(l0 * l0 * I), Mat2(l1 * l1 * I), dt) == Approx(2 * e / (1 + e * (t + 0.5 * dt))).epsilon(1e-6));
}

TEST_CASE("the membrane's power law with n = 1 is the standard linear solid, step for step", "[membrane3d]") {
  // A sphere whose vertices wander randomly: every triangle has its own strain rate, and n = 1
  // makes (102) constant, so the two memories must follow the same recursion (67). Round-off
  // only (1e-12: the same operations, perhaps contracted differently by the compiler).
  const Mesh ref = sphere_mesh(unit_icosphere(2), 5.0);
  const double E_m = 50.0, tau_m = 3.0;
  ElasticMembrane sls(ref, kNeoHookean, MaxwellElement{E_m, tau_m, 1.0});
  ElasticMembrane power(ref, kNeoHookean, MaxwellElement{E_m, tau_m, 1.0, PowerLawRelaxation{true, 1.0, 1e-3}});
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh cur = ref;
  for (int step = 0; step < 30; ++step) {
    for (auto& x : cur.x) x += 0.01 * Vec3(u(gen), u(gen), u(gen));
    std::vector<Vec3> f(cur.vertex_count(), Vec3::Zero()), g(cur.vertex_count(), Vec3::Zero());
    sls.add_forces(cur, f);
    power.add_forces(cur, g);
    double scale = 0, diff = 0;
    for (int v = 0; v < cur.vertex_count(); ++v) {
      scale = std::max(scale, f[v].norm());
      diff = std::max(diff, (f[v] - g[v]).norm());
    }
    REQUIRE(diff <= 1e-12 * scale);
  }
  REQUIRE(power.surface_shear_rates().size() == static_cast<std::size_t>(ref.triangle_count()));
}

TEST_CASE("the membrane's power law scales the viscous tension by (gamma / k)^(n - 1), floored", "[membrane3d]") {
  // One triangle sheared at a constant rate r per step. With tau much shorter than the time of
  // the strain (tau r <= 1e-3), the Maxwell tension is the Kelvin-Voigt one, tau_t dS_m/dt, so
  // the viscous force of n = 0.5 over that of n = 1 is tau_t / tau_m = (r / k)^(-1/2). The
  // strain stays below 1 %, where S_m is linear and the two laws see the same dS_m/dt; the
  // Kelvin-Voigt limit is then exact to O(tau r), so 0.5 % is the tolerance.
  const Mesh ref = single_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.9, 0));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const double k = 1e-3, E_m = 50.0, tau_m = 2.0;
  const ElasticMembrane spring(ref, kNeoHookean);
  auto viscous_ratio = [&](double rate_over_k, double& gamma_seen) {
    const double r = rate_over_k * k;
    ElasticMembrane newtonian(ref, kNeoHookean, MaxwellElement{E_m, tau_m, 1.0, PowerLawRelaxation{true, 1.0, k}});
    ElasticMembrane thinning(ref, kNeoHookean, MaxwellElement{E_m, tau_m, 1.0, PowerLawRelaxation{true, 0.5, k}});
    const int steps = 200;  // 100 tau_m, at most 32 tau_t
    std::vector<Vec3> fn, ft, fe;
    for (int step = 0; step <= steps; ++step) {
      const Mesh cur = deformed(ref, simple_shear(r * step), R);
      fn.assign(3, Vec3::Zero());
      ft.assign(3, Vec3::Zero());
      fe.assign(3, Vec3::Zero());
      newtonian.add_forces(cur, fn);
      thinning.add_forces(cur, ft);
      spring.add_elastic_forces(cur, fe);
    }
    gamma_seen = thinning.surface_shear_rates()[0];
    return (ft[1] - fe[1]).norm() / (fn[1] - fe[1]).norm();
  };
  double gamma = 0;
  CHECK(viscous_ratio(0.1, gamma) == Approx(std::pow(0.1, -0.5)).epsilon(0.005));
  CHECK(gamma == Approx(0.1).epsilon(1e-4));
  // Below the floor gamma / k = 0.01 the viscosity stops growing: 0.01^(-1/2) = 10, not 31.6.
  CHECK(viscous_ratio(0.001, gamma) == Approx(10.0).epsilon(0.005));
  CHECK(gamma == Approx(0.001).epsilon(1e-3));
}

TEST_CASE("the membrane power law's memory survives a restart", "[membrane3d]") {
  // memory() holds Q, S_m and C of the last step; a membrane restored from it continues with
  // exactly the forces of the one that kept running.
  const Mesh ref = sphere_mesh(unit_icosphere(1), 4.0);
  const MaxwellElement maxwell{50.0, 3.0, 1.0, PowerLawRelaxation{true, 0.6, 1e-3}};
  ElasticMembrane running(ref, kNeoHookean, maxwell), restored(ref, kNeoHookean, maxwell);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh cur = ref;
  std::vector<Vec3> f(cur.vertex_count(), Vec3::Zero()), g;
  for (int step = 0; step < 5; ++step) {
    for (auto& x : cur.x) x += 0.01 * Vec3(u(gen), u(gen), u(gen));
    running.add_forces(cur, f);
  }
  REQUIRE(running.memory().size() == 12u * ref.triangle_count());
  restored.restore_memory(running.memory(), running.memory_started());
  for (auto& x : cur.x) x += 0.01 * Vec3(u(gen), u(gen), u(gen));
  f.assign(cur.vertex_count(), Vec3::Zero());
  g.assign(cur.vertex_count(), Vec3::Zero());
  running.add_forces(cur, f);
  restored.add_forces(cur, g);
  for (int v = 0; v < cur.vertex_count(); ++v) REQUIRE(f[v] == g[v]);
  // A memory of the plain SLS (8 numbers a triangle) does not fit a power-law membrane.
  CHECK_THROWS(restored.restore_memory(std::vector<double>(8 * ref.triangle_count(), 0.0), true));
}
