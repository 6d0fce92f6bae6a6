#include "solver/membrane3d/membrane_forces.hpp"

#include <chrono>

#include "solver/membrane3d/surface_geometry.hpp"

namespace capsule::membrane3d {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

MembraneForces::MembraneForces(const Mesh& reference, const Mesh& start, MembraneParameters p)
    : elastic_(reference, p.law, p.maxwell), E_B_(p.E_B), K_v_(p.K_v), volume0_(enclosed_volume(start)) {
  if (p.c0.empty()) p.c0.assign(start.vertex_count(), 0.0);
  bending_ = HelfrichBending(p.E_B, std::move(p.c0));
}

void MembraneForces::compute(const Mesh& current, std::vector<Vec3>& force) {
  force.assign(current.vertex_count(), Vec3::Zero());
  auto t0 = std::chrono::steady_clock::now();
  elastic_.add_forces(current, force);
  timings_.elastic_s += seconds_since(t0);
  if (!needs_curvature()) return;
  t0 = std::chrono::steady_clock::now();
  // Into storage kept from the last step: the step allocates nothing.
  fit_curvatures(current, curvatures_);
  laplace_beltrami_.update(current);
  timings_.curvature_s += seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  if (E_B_ > 0) bending_.add_forces(curvatures_, laplace_beltrami_, force);
  if (K_v_ > 0) add_volume_penalty(K_v_, enclosed_volume(current), volume0_, curvatures_, laplace_beltrami_.areas(), force);
  timings_.bending_s += seconds_since(t0);
}

}  // namespace capsule::membrane3d
