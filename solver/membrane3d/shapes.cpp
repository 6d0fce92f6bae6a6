#include "solver/membrane3d/shapes.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

namespace capsule::membrane3d {

namespace {
// Thickness profile of (40) divided by a alpha / 2, as a function of sin^2 chi.
double profile(double s2) { return 0.207 + 2.003 * s2 - 1.123 * s2 * s2; }
}  // namespace

Mesh sphere_mesh(const Mesh& unit, double radius) {
  Mesh m = unit;
  for (auto& p : m.x) p = radius * p.normalized();
  return m;
}

double biconcave_scale_for_unit_equivalent_radius() {
  // Volume of revolution about y: V = -int_0^pi pi r(chi)^2 y'(chi) dchi with r = alpha sin chi,
  // y = (alpha/2) profile(sin^2 chi) cos chi (signed, so the dimple is handled exactly).
  const double al = biconcave_alpha;
  auto integrand = [al](double chi) {
    const double s = std::sin(chi), c = std::cos(chi), s2 = s * s;
    const double dprofile = (2.003 - 2.246 * s2) * 2.0 * s * c;  // d profile / d chi
    const double dy = 0.5 * al * (dprofile * c - profile(s2) * s);
    const double r = al * s;
    return -std::numbers::pi * r * r * dy;
  };
  const double volume =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, 0.0, std::numbers::pi, 15, 1e-13);
  return std::cbrt((4.0 / 3.0) * std::numbers::pi / volume);
}

Mesh biconcave_mesh(const Mesh& unit, double equivalent_radius) {
  const double s = biconcave_scale_for_unit_equivalent_radius() * equivalent_radius;
  const double al = biconcave_alpha;
  Mesh m = unit;
  for (auto& p : m.x) {
    const Vec3 u = p.normalized();
    const double s2 = u.x() * u.x() + u.z() * u.z();  // sin^2 chi
    // (39)-(41): x = a alpha sin chi cos phi, y = (a alpha/2) profile cos chi, z = a alpha sin chi sin phi
    p = Vec3(s * al * u.x(), 0.5 * s * al * profile(s2) * u.y(), s * al * u.z());
  }
  return m;
}

void rotate_about_z_and_translate(Mesh& mesh, double angle, const Vec3& centre) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (auto& p : mesh.x) p = Vec3(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()) + centre;
}

}  // namespace capsule::membrane3d
