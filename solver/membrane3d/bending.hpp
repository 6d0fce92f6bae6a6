#pragma once
// Helfrich bending (71)-(72) on the triangulated membrane.
//
// Energy (71): W_b = (E_B/2) int (2 kappa - c0)^2 dS, kappa the mean curvature, POSITIVE on a
// sphere with the outward normal (curvature.hpp). E_B = E_b a E_s (35): the dissertation's
// E_b = E_B/(a E_s) with this W_b (papers with W = (k/2) int (k1 + k2 - c0)^2 dS have k = E_B;
// with E_b' = E_B/(a^2 E_s) and a lengths in units of a, E_b' = E_b / a).
//
// Force density (first variation of (71), outward normal, kappa > 0 on a sphere):
//   f_b = E_B [ (2 kappa - c0)(2 kappa^2 - 2 kappa_g + c0 kappa) + 2 Delta_LB kappa ] n.
// (72) as printed, E_B [(2 kappa + c0)(2 kappa^2 - 2 kappa_g - c0 kappa) + 2 Delta kappa] n, is
// Ou-Yang and Helfrich's equation in their convention (mean curvature NEGATIVE on a sphere,
// inward normal); substituting kappa -> -kappa, n -> -n gives the form above. Check: a sphere
// of radius R has W_b = 2 pi E_B (2 - c0 R)^2, so -dW_b/dR / (4 pi R^2) = E_B c0 (2/R - c0)/R,
// which is the formula above (c0 < 0 pushes a sphere inward). The nodal force is
// f_b times the Voronoi area (83).
#include <vector>

#include "solver/membrane3d/curvature.hpp"
#include "solver/membrane3d/surface_geometry.hpp"

namespace capsule::membrane3d {

class HelfrichBending {
 public:
  HelfrichBending() = default;
  // c0 per vertex (constant c0: all equal; Table 1 case B: c0 = 2 kappa of the start shape).
  HelfrichBending(double E_B, std::vector<double> c0) : E_B_(E_B), c0_(std::move(c0)) {}

  // Nodal forces f_b a_vor along the fitted normals, added to `force`.
  void add_forces(const Curvatures& k, const LaplaceBeltrami& lb, std::vector<Vec3>& force) const;
  // Discrete (71): (E_B/2) sum_p (2 kappa_p - c0_p)^2 a_vor(p).
  double energy(const Curvatures& k, const std::vector<double>& voronoi_area) const;
  double modulus() const { return E_B_; }
  const std::vector<double>& spontaneous_curvature() const { return c0_; }

 private:
  double E_B_ = 0;
  std::vector<double> c0_;
  mutable std::vector<double> laplacian_;  // scratch of add_forces, kept so a step allocates nothing
};

// Volume penalty (84): an isotropic pressure -K_v (V_c - V_c0)/V_c0 along the outward normal
// (restoring: a swollen capsule is pushed in), nodal force = pressure times a_vor.
void add_volume_penalty(double K_v, double volume, double volume0, const Curvatures& k,
                        const std::vector<double>& voronoi_area, std::vector<Vec3>& force);

}  // namespace capsule::membrane3d
