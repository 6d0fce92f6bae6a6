#include "solver/membrane3d/phase_angles.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace capsule::membrane3d {

namespace {
constexpr double pi = std::numbers::pi;
double gamma_of(const Vec3& p, const Vec3& c, double theta) { return std::atan2(p.y() - c.y(), p.x() - c.x()) - theta; }  // (91)
// a - b brought into (-pi/2, pi/2] (positions are equivalent modulo pi)
double mod_pi_difference(double a, double b) {
  double d = std::remainder(a - b, pi);
  if (d <= -pi / 2) d += pi;
  return d;
}
}  // namespace

PhaseTracker::PhaseTracker(const Mesh& m, const Vec3& c, double theta0) {
  // Vertices within a thin slab about the shear plane through the centroid.
  double extent = 0;
  for (const auto& p : m.x) extent = std::max(extent, (p - c).norm());
  double slab = 0.02 * extent;
  std::vector<int> near;
  while (near.size() < 20) {
    near.clear();
    for (int v = 0; v < m.vertex_count(); ++v)
      if (std::abs(m.x[v].z() - c.z()) <= slab) near.push_back(v);
    slab *= 1.5;
  }
  for (int k = 0; k < 5; ++k) {
    const double target = k * pi / 8.0;
    int best = -1;
    double best_err = std::numeric_limits<double>::infinity();
    for (int v : near) {
      const double err = std::abs(mod_pi_difference(gamma_of(m.x[v], c, theta0), target));
      if (err < best_err) best_err = err, best = v;
    }
    vertex_.push_back(best);
    gamma0_.push_back(gamma_of(m.x[best], c, theta0));
  }
  gamma_ = gamma0_;
}

std::vector<double> PhaseTracker::update(const Mesh& m, const Vec3& c, double theta) {
  std::vector<double> beta(vertex_.size());
  for (std::size_t k = 0; k < vertex_.size(); ++k) {
    const double raw = gamma_of(m.x[vertex_[k]], c, theta);
    gamma_[k] += mod_pi_difference(raw, gamma_[k]);  // continuous modulo pi
    beta[k] = gamma_[k] - gamma0_[k];                // (92)
  }
  return beta;
}

}  // namespace capsule::membrane3d
