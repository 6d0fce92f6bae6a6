#pragma once
// All membrane forces of the 3D capsule in one place: FEM elasticity (55) (+ SLS (63)-(67)),
// Helfrich bending (71)-(72) and the volume penalty (84). A term whose coefficient is zero is
// skipped (and so is the curvature fit when neither bending nor the penalty needs it).
#include <vector>

#include "solver/membrane3d/bending.hpp"
#include "solver/membrane3d/curvature.hpp"
#include "solver/membrane3d/elasticity.hpp"

namespace capsule::membrane3d {

struct MembraneParameters {
  Constitutive law;               // E_s, law, C
  MaxwellElement maxwell;         // E_m = 0: elastic
  double E_B = 0;                 // bending modulus (35)
  std::vector<double> c0;         // per-vertex spontaneous curvature (empty: 0)
  double K_v = 0;                 // volume-penalty pressure scale (84)
};

struct MembraneTimings {
  double elastic_s = 0, curvature_s = 0, bending_s = 0;  // accumulated wall seconds
};

class MembraneForces {
 public:
  MembraneForces() = default;
  // reference: stress-free triangles; start: the initial shape (its volume is V_c0 of (84)).
  MembraneForces(const Mesh& reference, const Mesh& start, MembraneParameters p);

  // Sets force = sum of all membrane nodal forces at `current` (advances SLS memory).
  void compute(const Mesh& current, std::vector<Vec3>& force);
  const MembraneTimings& timings() const { return timings_; }
  double volume0() const { return volume0_; }
  const ElasticMembrane& elastic() const { return elastic_; }
  ElasticMembrane& elastic() { return elastic_; }  // restart points restore the SLS memory
  void set_timings(const MembraneTimings& t) { timings_ = t; }
  const HelfrichBending& bending() const { return bending_; }
  bool needs_curvature() const { return E_B_ > 0 || K_v_ > 0; }

 private:
  ElasticMembrane elastic_;
  HelfrichBending bending_;
  double E_B_ = 0, K_v_ = 0, volume0_ = 0;
  MembraneTimings timings_;
  Curvatures curvatures_;             // of the last step, storage reused
  LaplaceBeltrami laplace_beltrami_;  // of the last step, storage reused
};

}  // namespace capsule::membrane3d
