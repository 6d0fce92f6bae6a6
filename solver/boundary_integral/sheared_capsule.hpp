#pragma once
// A capsule in unbounded simple shear by the boundary-integral method: the independent
// reference for the lattice solver's 3D members (docs/findings/boundary_integral_reference.md).
//
// Equal viscosities inside and out (V = 1), zero Reynolds number, no walls. Units: the
// capsule radius a, the shear rate k and the fluid viscosity mu are 1, so time is kt and the
// elastic modulus E_s = 1/Ca (34). The imposed flow is u_inf = (k y, 0, 0) about the
// capsule's centre at the origin. The membrane is the toolkit's own: the icosphere of
// `level`, the FEM elastic forces (55) with the neo-Hookean or Skalak law in the toolkit's
// convention (constitutive_law.hpp law_modulus), and Helfrich bending (71)-(72) with
// E_B = E_b a^2 E_s. The membrane forces q (exerted on the fluid) give the vertex velocities
//   U_i = u_inf(x_i) + (1/(8 pi mu)) int G(x_i - y) q(y) dS(y)        (single_layer.hpp)
// with q = F_j / A_j at the vertices, the discrete volume kept by removing the net flux
// (remove_volume_flux). The vertices move with U by Heun's second-order scheme.
//
// Time step: explicit, so bounded by the fastest membrane mode, whose relaxation rate is
// about G_s/(mu h) for in-plane elasticity and E_B/(mu h^3) for bending (h the shortest edge):
// dt = cfl min(mu h / G_s, mu h^3 / E_B) / k.
#include <string>
#include <vector>

#include "solver/boundary_integral/single_layer.hpp"
#include "solver/membrane3d/membrane_forces.hpp"

namespace capsule::boundary_integral {

struct ShearedCapsuleParameters {
  double Ca = 0.1;                   // mu k a / E_s (34)
  membrane3d::ElasticLaw law = membrane3d::ElasticLaw::neo_hookean;
  double C = 15;                     // Skalak area-dilation constant
  double E_b = 0;                    // E_B / (a^2 E_s)
  int level = 3;                     // icosphere refinement (642 vertices at 3)
  double cfl = 0.5;                  // fraction of the explicit limit above
  double dt = 0;                     // > 0: this time step (kt units) instead of the cfl rule
  SingleLayerOptions quadrature;
};

struct CapsuleShape {
  double kt = 0;
  double D = 0;            // Taylor deformation of the inertia-equivalent ellipsoid (37)-(38)
  double theta = 0;        // its inclination to the flow direction, rad
  double L = 0, W = 0;     // its full axes in the shear plane, in units of a
  double extent_D = 0;     // (r_max - r_min)/(r_max + r_min) of the z = 0 section
  double volume_change = 0, area_change = 0;  // relative to the start
};

class ShearedCapsule {
 public:
  explicit ShearedCapsule(const ShearedCapsuleParameters& p);

  // Advances one time step (Heun).
  void step();
  // Vertex velocities of the current shape (the two halves of a step call this).
  void velocity(const membrane3d::Mesh& mesh, std::vector<Vec3>& U);

  CapsuleShape shape() const;
  const membrane3d::Mesh& mesh() const { return mesh_; }
  double kt() const { return steps_ * dt_; }
  double dt() const { return dt_; }
  long steps() const { return steps_; }

 private:
  ShearedCapsuleParameters p_;
  SingleLayer single_layer_;
  membrane3d::Mesh mesh_, predicted_;
  membrane3d::MembraneForces forces_;
  double dt_ = 0, volume0_ = 0, area0_ = 0;
  long steps_ = 0;
  std::vector<Vec3> force_, q_, U1_, U2_;
};

}  // namespace capsule::boundary_integral
