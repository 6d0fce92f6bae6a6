#include "solver/boundary_integral/sheared_capsule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solver/membrane3d/shape_measures.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "solver/membrane3d/surface_geometry.hpp"

namespace capsule::boundary_integral {

namespace m3 = membrane3d;

namespace {

double shortest_edge(const m3::Mesh& mesh) {
  double h = std::numeric_limits<double>::infinity();
  for (const auto& e : mesh.edges) h = std::min(h, (mesh.x[e[0]] - mesh.x[e[1]]).norm());
  return h;
}

m3::MembraneForces membrane_for(const ShearedCapsuleParameters& p, const m3::Mesh& sphere) {
  if (!(p.Ca > 0)) throw std::invalid_argument("reference-bim: Ca must be > 0, got " + std::to_string(p.Ca));
  if (p.E_b < 0) throw std::invalid_argument("reference-bim: E_b must be >= 0, got " + std::to_string(p.E_b));
  if (p.level < 1 || p.level > 6)
    throw std::invalid_argument("reference-bim: mesh level must be 1-6, got " + std::to_string(p.level));
  const double E_s = 1.0 / p.Ca;  // a = k = mu = 1
  m3::MembraneParameters mp;
  mp.law = m3::Constitutive{p.law, m3::law_modulus(p.law, E_s), p.C};
  mp.E_B = p.E_b * E_s;  // E_B = E_b a^2 E_s
  return m3::MembraneForces(sphere, sphere, mp);
}

}  // namespace

ShearedCapsule::ShearedCapsule(const ShearedCapsuleParameters& p)
    : p_(p), single_layer_(p.quadrature), mesh_(m3::sphere_mesh(m3::unit_icosphere(std::clamp(p.level, 1, 6)), 1.0)),
      forces_(membrane_for(p, mesh_)) {
  predicted_ = mesh_;
  const double E_s = 1.0 / p.Ca, mu = p.quadrature.viscosity;
  const double G_s = m3::law_modulus(p.law, E_s);
  const double h = shortest_edge(mesh_);
  double limit = mu * h / G_s;
  if (p.E_b > 0) limit = std::min(limit, mu * h * h * h / (p.E_b * E_s));
  dt_ = p.dt > 0 ? p.dt : p.cfl * limit;
  if (!(dt_ > 0)) throw std::invalid_argument("reference-bim: the time step must be > 0 (cfl or dt)");
  volume0_ = m3::enclosed_volume(mesh_);
  area0_ = m3::surface_area(mesh_);
}

void ShearedCapsule::velocity(const m3::Mesh& mesh, std::vector<Vec3>& U) {
  forces_.compute(mesh, force_);
  const std::vector<double> A = lumped_vertex_areas(mesh);
  q_.resize(force_.size());
  for (std::size_t j = 0; j < q_.size(); ++j) q_[j] = force_[j] / A[j];
  single_layer_.velocity(mesh, q_, U);
  for (std::size_t j = 0; j < U.size(); ++j) U[j].x() += mesh.x[j].y();  // u_inf = (k y, 0, 0)
  remove_volume_flux(mesh, U);
}

void ShearedCapsule::step() {
  velocity(mesh_, U1_);
  for (int j = 0; j < mesh_.vertex_count(); ++j) predicted_.x[j] = mesh_.x[j] + dt_ * U1_[j];
  velocity(predicted_, U2_);
  for (int j = 0; j < mesh_.vertex_count(); ++j) {
    mesh_.x[j] += 0.5 * dt_ * (U1_[j] + U2_[j]);
    if (!mesh_.x[j].allFinite())
      throw std::runtime_error("reference-bim: unstable at kt = " + std::to_string(kt()) + " (a vertex is not finite)");
  }
  ++steps_;
}

CapsuleShape ShearedCapsule::shape() const {
  const auto d = m3::inertia_deformation(mesh_);
  CapsuleShape s;
  s.kt = kt();
  s.D = d.D;
  s.theta = d.theta;
  s.L = d.L;
  s.W = d.W;
  s.extent_D = m3::extent_deformation(mesh_, d.centroid);
  s.volume_change = m3::enclosed_volume(mesh_) / volume0_ - 1.0;
  s.area_change = m3::surface_area(mesh_) / area0_ - 1.0;
  return s;
}

}  // namespace capsule::boundary_integral
