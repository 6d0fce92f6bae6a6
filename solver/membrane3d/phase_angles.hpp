#pragma once
// Phase angles of tracked membrane elements, (91)-(92): Gamma = alpha_xy - theta_xy and
// beta(t) = Gamma(t) - Gamma(0), for five vertices near the shear plane through the centroid
// whose initial positions are Gamma(0) = 0, pi/8, pi/4, 3 pi/8, pi/2 (Fig. 39).
// The capsule is symmetric under a half turn, so a position and the one opposite are the
// same (Sec. 4.2.1): Gamma is followed continuously modulo pi (no jumps when theta wraps),
// and beta accumulates whole half turns of tank-treading.
#include <vector>

#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d {

class PhaseTracker {
 public:
  PhaseTracker() = default;
  // Chooses the tracked vertices on the start shape (centroid c, inclination theta0).
  PhaseTracker(const Mesh& start, const Vec3& centroid, double theta0);
  // beta (92) of every tracked vertex for the current shape.
  std::vector<double> update(const Mesh& current, const Vec3& centroid, double theta);
  const std::vector<int>& vertices() const { return vertex_; }
  const std::vector<double>& initial_positions() const { return gamma0_; }
  // Restart points: the continuous Gamma of each tracked vertex (the rest follows from the start shape).
  const std::vector<double>& continuous_positions() const { return gamma_; }
  void restore(const std::vector<double>& gamma) { gamma_ = gamma; }

 private:
  std::vector<int> vertex_;
  std::vector<double> gamma0_, gamma_;  // Gamma(0) and the continuous Gamma
};

}  // namespace capsule::membrane3d
