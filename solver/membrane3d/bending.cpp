#include "solver/membrane3d/bending.hpp"

namespace capsule::membrane3d {

void HelfrichBending::add_forces(const Curvatures& k, const LaplaceBeltrami& lb, std::vector<Vec3>& force) const {
  std::vector<double>& lap = laplacian_;
  lb.apply(k.mean, lap);
  const auto& area = lb.areas();
  const int nv = static_cast<int>(force.size());
  for (int p = 0; p < nv; ++p) {
    const double kap = k.mean[p], kg = k.gaussian[p], c0 = c0_[p];
    const double fb = E_B_ * ((2.0 * kap - c0) * (2.0 * kap * kap - 2.0 * kg + c0 * kap) + 2.0 * lap[p]);
    force[p] += fb * area[p] * k.normal[p];
  }
}

double HelfrichBending::energy(const Curvatures& k, const std::vector<double>& area) const {
  double w = 0;
  for (std::size_t p = 0; p < area.size(); ++p) {
    const double h = 2.0 * k.mean[p] - c0_[p];
    w += h * h * area[p];
  }
  return 0.5 * E_B_ * w;
}

void add_volume_penalty(double K_v, double volume, double volume0, const Curvatures& k,
                        const std::vector<double>& area, std::vector<Vec3>& force) {
  const double pressure = -K_v * (volume - volume0) / volume0;  // (84)
  for (std::size_t p = 0; p < force.size(); ++p) force[p] += pressure * area[p] * k.normal[p];
}

}  // namespace capsule::membrane3d
