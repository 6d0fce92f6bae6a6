// The single-layer potential on a sphere against the exact single layers of rigid-body
// tractions (a = mu = 1; Pozrikidis 1992, Sec. 2.3 and 4.6; Kim and Karrila 1991, Ch. 2):
//   uniform q:             the sphere translates, u = (2/3) q a / mu   (Stokes drag 6 pi mu a U = 4 pi a^2 q)
//   q = n (a pressure):    u = 0 (int G n dS = 0 on a closed surface)
//   q = omega x n:         u = omega x x / 3 (the torque 8 pi mu a^3 omega of a rotating sphere)
//   q = E n (E traceless): u = E x / 5 (the stresslet (20/3) pi mu a^3 E of a sphere in strain)
// The discretisation is second order in the mesh spacing h ~ 1/2^level (linear q, flat
// triangles, trapezoid far field beyond a near zone of fixed radius). Measured at level 3 / 4:
// uniform 0.34 / 0.083 %, pressure 0.078 % / -, rotation 0.26 / 0.061 %, strain 0.17 / 0.036 %.
// The tolerances are the level-3 error with a margin of about two, and the error must fall by
// at least three (of the ideal four) from level 3 to 4.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "solver/boundary_integral/single_layer.hpp"
#include "solver/membrane3d/shapes.hpp"

using namespace capsule;
using boundary_integral::SingleLayer;
using boundary_integral::Vec3;

namespace {

// Largest |u_i - exact(x_i)| over the vertices, relative to max |exact|.
double relative_error(int level, const std::function<Vec3(const Vec3&)>& density,
                      const std::function<Vec3(const Vec3&)>& exact, double scale) {
  const auto mesh = membrane3d::sphere_mesh(membrane3d::unit_icosphere(level), 1.0);
  std::vector<Vec3> q(mesh.vertex_count()), u;
  for (int i = 0; i < mesh.vertex_count(); ++i) q[i] = density(mesh.x[i].normalized());
  SingleLayer(boundary_integral::SingleLayerOptions{}).velocity(mesh, q, u);
  double worst = 0;
  for (int i = 0; i < mesh.vertex_count(); ++i) worst = std::max(worst, (u[i] - exact(mesh.x[i])).norm());
  return worst / scale;
}

}  // namespace

TEST_CASE("single layer: a uniform traction translates the sphere at (2/3) q a / mu", "[boundary_integral]") {
  const Vec3 f(0.3, -1.0, 0.5);
  auto err = [&](int level) {
    return relative_error(level, [&](const Vec3&) { return f; }, [&](const Vec3&) { return (2.0 / 3.0) * f; },
                          (2.0 / 3.0) * f.norm());
  };
  const double e3 = err(3), e4 = err(4);
  INFO("level 3: " << e3 << ", level 4: " << e4);
  CHECK(e3 < 6e-3);
  CHECK(e3 / e4 > 3.0);
}

TEST_CASE("single layer: a uniform pressure moves nothing", "[boundary_integral]") {
  const double e3 = relative_error(3, [](const Vec3& n) { return n; }, [](const Vec3&) { return Vec3::Zero(); }, 1.0);
  INFO("level 3: " << e3);
  CHECK(e3 < 2e-3);
}

TEST_CASE("single layer: omega x n rotates the sphere at omega / 3", "[boundary_integral]") {
  const Vec3 w(0.2, 0.4, -1.0);
  auto err = [&](int level) {
    return relative_error(level, [&](const Vec3& n) { return Vec3(w.cross(n)); },
                          [&](const Vec3& x) { return Vec3(w.cross(x) / 3.0); }, w.norm() / 3.0);
  };
  const double e3 = err(3), e4 = err(4);
  INFO("level 3: " << e3 << ", level 4: " << e4);
  CHECK(e3 < 5e-3);
  CHECK(e3 / e4 > 3.0);
}

TEST_CASE("single layer: E n gives the strain E x / 5 (a free sphere in shear cancels the strain)", "[boundary_integral]") {
  Eigen::Matrix3d E;
  E << 0.1, 0.5, 0.0, 0.5, 0.3, 0.2, 0.0, 0.2, -0.4;  // symmetric, traceless
  auto err = [&](int level) {
    return relative_error(level, [&](const Vec3& n) { return Vec3(E * n); },
                          [&](const Vec3& x) { return Vec3(E * x / 5.0); }, E.norm() / 5.0);
  };
  const double e3 = err(3), e4 = err(4);
  INFO("level 3: " << e3 << ", level 4: " << e4);
  CHECK(e3 < 4e-3);
  CHECK(e3 / e4 > 3.0);
}

TEST_CASE("single layer: the volume-flux correction removes an expansion and keeps a shear", "[boundary_integral]") {
  const auto mesh = membrane3d::sphere_mesh(membrane3d::unit_icosphere(2), 1.0);
  const auto g = boundary_integral::volume_gradient(mesh);
  // A linear field u = L x changes the polyhedron's volume at the rate tr(L) V exactly: the
  // shear (tr L = 0) has no flux and is left as it is, to rounding.
  std::vector<Vec3> shear(mesh.vertex_count());
  for (int i = 0; i < mesh.vertex_count(); ++i) shear[i] = Vec3(mesh.x[i].y(), 0, 0);
  std::vector<Vec3> u = shear;
  CHECK(std::abs(boundary_integral::remove_volume_flux(mesh, u)) < 1e-14);
  for (int i = 0; i < mesh.vertex_count(); ++i) CHECK((u[i] - shear[i]).norm() < 1e-14);
  // With an expansion added, the corrected field no longer changes the volume.
  for (int i = 0; i < mesh.vertex_count(); ++i) u[i] = shear[i] + 0.1 * mesh.x[i];
  CHECK(boundary_integral::remove_volume_flux(mesh, u) > 0);
  double rate = 0;
  for (int i = 0; i < mesh.vertex_count(); ++i) rate += u[i].dot(g[i]);
  CHECK(std::abs(rate) < 1e-12);
}
