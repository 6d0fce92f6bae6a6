// FEM membrane elasticity (55) with the neo-Hookean (56), (58)-(59) and Skalak (60)-(61) laws,
// and the standard linear solid (63)-(67).
#include <catch2/catch.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "solver/membrane3d/elasticity.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "tests/solver/membrane3d/single_triangle.hpp"

using namespace capsule::membrane3d;
using capsule::membrane3d::testing::single_triangle;

namespace {

Eigen::Matrix3d rotation(double angle, const Vec3& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

// Mesh with every vertex moved randomly by up to `amplitude` times the radius.
Mesh perturbed(const Mesh& m, double amplitude, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh p = m;
  const double R = m.x[0].norm();
  for (auto& x : p.x) x += amplitude * R * Vec3(u(gen), u(gen), u(gen));
  return p;
}

}  // namespace

TEST_CASE("a triangle under a known stretch gives the analytic neo-Hookean and Skalak stresses", "[membrane3d]") {
  const double l1 = 1.3, l2 = 0.85, phi = 0.4;  // principal stretches, direction of lambda_1 in the reference plane
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.3, 0.8, 0);
  // Current = rigid rotation o (stretch l1 along (cos phi, sin phi), l2 across) of the reference.
  const Eigen::Vector2d d1(std::cos(phi), std::sin(phi)), d2(-std::sin(phi), std::cos(phi));
  const Eigen::Matrix2d U = l1 * d1 * d1.transpose() + l2 * d2 * d2.transpose();
  Eigen::Matrix3d U3 = Eigen::Matrix3d::Identity();
  U3.topLeftCorner<2, 2>() = U;
  const Eigen::Matrix3d Q = rotation(0.9, Vec3(0.3, -1.0, 0.5));
  const Vec3 shift(2.0, -1.0, 0.5);
  const Mesh ref = single_triangle(a, b, c);
  const Mesh cur = single_triangle(Q * U3 * a + shift, Q * U3 * b + shift, Q * U3 * c + shift);
  for (auto law : {ElasticLaw::neo_hookean, ElasticLaw::skalak}) {
    Constitutive k{law, 2.5, 15.0};
    const ElasticMembrane membrane(ref, k);
    std::vector<Vec3> f(3, Vec3::Zero());
    membrane.add_elastic_forces(cur, f);
    // Analytic Cauchy tension (62) from the printed principal values (58)-(61), in 3D.
    const auto [s1, s2] = k.principal_cauchy(l1, l2);
    const Vec3 e1 = Q * Vec3(d1.x(), d1.y(), 0), e2 = Q * Vec3(d2.x(), d2.y(), 0);
    const Eigen::Matrix3d sigma = s1 * e1 * e1.transpose() + s2 * e2 * e2.transpose();
    // A uniformly stressed linear triangle: the force on a vertex is half the traction on the
    // opposite edge, (1/2) sigma (l nu), nu the in-plane outward normal of that edge.
    const Vec3 n = (cur.x[1] - cur.x[0]).cross(cur.x[2] - cur.x[0]).normalized();
    for (int v = 0; v < 3; ++v) {
      const Vec3 p = cur.x[(v + 1) % 3], q = cur.x[(v + 2) % 3];
      const Vec3 l_nu = (q - p).cross(n);  // |q - p| times the outward edge normal (counter-clockwise order)
      const Vec3 expected = 0.5 * sigma * l_nu;
      INFO("law " << capsule::choice_name(law) << " vertex " << v);
      // Both sides are exact formulas; the difference is round-off (1e-12 relative).
      CHECK((f[v] - expected).norm() < 1e-12 * expected.norm());
    }
  }
}

TEST_CASE("rigid rotations and translations give zero elastic force", "[membrane3d]") {
  const Mesh ref = biconcave_mesh(unit_icosphere(3), 10.0);
  Mesh moved = ref;
  const Eigen::Matrix3d Q = rotation(2.1, Vec3(1, 2, -0.5));
  for (auto& x : moved.x) x = Q * x + Vec3(3.0, -7.0, 11.0);
  for (auto law : {ElasticLaw::neo_hookean, ElasticLaw::skalak}) {
    const ElasticMembrane membrane(ref, Constitutive{law, 1.0, 15.0});
    std::vector<Vec3> f(moved.vertex_count(), Vec3::Zero());
    membrane.add_elastic_forces(moved, f);
    double fmax = 0;
    for (const auto& x : f) fmax = std::max(fmax, x.norm());
    // Force scale is E_s times an edge (~1.5 here); round-off in C - I is ~1e-15, so 1e-11 is
    // far below any real force and far above round-off.
    CHECK(fmax < 1e-11);
    CHECK(membrane.energy(moved) < 1e-11);
  }
}

TEST_CASE("total elastic force and torque vanish on a deformed mesh", "[membrane3d]") {
  const Mesh ref = sphere_mesh(unit_icosphere(3), 10.0);
  const Mesh cur = perturbed(ref, 0.03, 7);
  for (auto law : {ElasticLaw::neo_hookean, ElasticLaw::skalak}) {
    const ElasticMembrane membrane(ref, Constitutive{law, 1.0, 15.0});
    std::vector<Vec3> f(cur.vertex_count(), Vec3::Zero());
    membrane.add_elastic_forces(cur, f);
    Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
    double scale = 0;
    for (int v = 0; v < cur.vertex_count(); ++v) {
      total += f[v];
      torque += cur.x[v].cross(f[v]);
      scale += f[v].norm();
    }
    REQUIRE(scale > 1.0);  // the perturbation does load the membrane
    // Each triangle's three forces sum to zero and have zero moment exactly; round-off only.
    CHECK(total.norm() < 1e-12 * scale);
    CHECK(torque.norm() < 1e-12 * scale * 10.0);
  }
}

TEST_CASE("elastic forces are minus the gradient of the discrete energy", "[membrane3d]") {
  const Mesh ref = sphere_mesh(unit_icosphere(2), 10.0);
  const Mesh cur = perturbed(ref, 0.05, 11);
  for (auto law : {ElasticLaw::neo_hookean, ElasticLaw::skalak}) {
    const ElasticMembrane membrane(ref, Constitutive{law, 1.3, 15.0});
    std::vector<Vec3> f(cur.vertex_count(), Vec3::Zero());
    membrane.add_elastic_forces(cur, f);
    const double h = 1e-5;  // central differences: truncation ~h^2 W''' ~1e-10, round-off ~1e-16 E / h ~1e-9
    double max_err = 0, max_f = 0;
    for (int v = 0; v < cur.vertex_count(); v += 7) {
      for (int d = 0; d < 3; ++d) {
        Mesh plus = cur, minus = cur;
        plus.x[v][d] += h;
        minus.x[v][d] -= h;
        const double grad = (membrane.energy(plus) - membrane.energy(minus)) / (2 * h);
        max_err = std::max(max_err, std::abs(-grad - f[v][d]));
        max_f = std::max(max_f, std::abs(f[v][d]));
      }
    }
    INFO("law " << capsule::choice_name(law) << ": max |f + dE/dx| = " << max_err << " of max |f| = " << max_f);
    CHECK(max_err < 1e-6 * max_f);
  }
}

TEST_CASE("Skalak energy as written with I1 reproduces the printed stresses (60)-(61)", "[membrane3d]") {
  // sigma_1 = (1/lambda_2) dW/dlambda_1 (58)/(60): checks that the energy form used (standard
  // Skalak, not the misprinted (57)) is the one whose derivatives the text prints.
  for (auto law : {ElasticLaw::neo_hookean, ElasticLaw::skalak}) {
    const Constitutive k{law, 1.7, 15.0};
    const double l1 = 1.2, l2 = 0.9, h = 1e-6;
    auto W = [&](double a, double b) { return k.energy_density(Mat2(Eigen::Vector2d(a * a, b * b).asDiagonal())); };
    const double s1 = (W(l1 + h, l2) - W(l1 - h, l2)) / (2 * h) / l2;
    const double s2 = (W(l1, l2 + h) - W(l1, l2 - h)) / (2 * h) / l1;
    const auto [p1, p2] = k.principal_cauchy(l1, l2);
    CHECK(s1 == Approx(p1).epsilon(1e-7));  // central difference, h^2 ~ 1e-12 relative truncation
    CHECK(s2 == Approx(p2).epsilon(1e-7));
  }
}

TEST_CASE("standard linear solid relaxes a step stretch with tau_m", "[membrane3d]") {
  // Equibiaxial step stretch held fixed: the Maxwell tension jumps to ~the E_m law and decays
  // as exp(-t/tau_m), leaving the elastic E_s tension.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 0.8, 0);
  const double lambda = 1.1, E_s = 1.0, E_m = 50.0, tau_m = 40.0, dt = 1.0;
  const Mesh ref = single_triangle(a, b, c);
  const Mesh cur = single_triangle(lambda * a, lambda * b, lambda * c);
  ElasticMembrane sls(ref, Constitutive{ElasticLaw::neo_hookean, E_s, 15.0}, MaxwellElement{E_m, tau_m, dt});
  const ElasticMembrane spring(ref, Constitutive{ElasticLaw::neo_hookean, E_s, 15.0});
  const ElasticMembrane maxwell_spring(ref, Constitutive{ElasticLaw::neo_hookean, E_m, 15.0});
  std::vector<Vec3> f(3, Vec3::Zero()), fe(3, Vec3::Zero()), fm(3, Vec3::Zero());
  sls.add_forces(ref, f);  // start: memory at the reference state
  spring.add_elastic_forces(cur, fe);
  maxwell_spring.add_elastic_forces(cur, fm);
  const double gain = tau_m / dt * (1 - std::exp(-dt / tau_m));  // (67) weight of a jump within one step
  for (int n = 1; n <= 80; ++n) {
    f.assign(3, Vec3::Zero());
    sls.add_forces(cur, f);
    const Vec3 expected = fe[1] + gain * std::exp(-(n - 1) * dt / tau_m) * fm[1];
    REQUIRE((f[1] - expected).norm() < 1e-12 * expected.norm());  // exact recursion: round-off only
  }
}

TEST_CASE("a Skalak membrane's Maxwell element is Skalak's law without its area term (with it under physics version 5)",
          "[membrane3d]") {
  // The same equibiaxial step as above, on a Skalak law with C = 100: an area change only, where
  // the area term is all but 1/201 of the stiffness. The element's tension must be Skalak's at E_m
  // with C = 0 (a shear viscosity), or with C = 100 when it keeps the area term (version 5).
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 0.8, 0);
  const double lambda = 1.1, E_s = 1.0, E_m = 50.0, tau_m = 40.0, dt = 1.0, C = 100.0;
  const Mesh ref = single_triangle(a, b, c);
  const Mesh cur = single_triangle(lambda * a, lambda * b, lambda * c);
  const double gain = tau_m / dt * (1 - std::exp(-dt / tau_m));  // (67) weight of a jump within one step
  for (const bool area_term : {false, true}) {
    MaxwellElement element{E_m, tau_m, dt};
    element.skalak_area_term = area_term;
    ElasticMembrane sls(ref, Constitutive{ElasticLaw::skalak, E_s, C}, element);
    const ElasticMembrane spring(ref, Constitutive{ElasticLaw::skalak, E_s, C});
    const ElasticMembrane maxwell_spring(ref, Constitutive{ElasticLaw::skalak, E_m, area_term ? C : 0.0});
    std::vector<Vec3> f(3, Vec3::Zero()), fe(3, Vec3::Zero()), fm(3, Vec3::Zero());
    sls.add_forces(ref, f);  // start: memory at the reference state
    spring.add_elastic_forces(cur, fe);
    maxwell_spring.add_elastic_forces(cur, fm);
    f.assign(3, Vec3::Zero());
    sls.add_forces(cur, f);
    const Vec3 expected = fe[1] + gain * fm[1];
    INFO("area term in the element: " << area_term);
    CHECK((f[1] - expected).norm() < 1e-12 * expected.norm());  // exact recursion: round-off only
  }
}
