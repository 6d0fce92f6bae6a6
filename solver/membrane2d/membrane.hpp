#pragma once
// The 2D capsule membrane (Sec. 2.4): a closed chain of line segments with
//   in-plane tension   tau = tau_e + tau_v                             (28)
//     elastic          tau_e(lambda), lambda = l / l0: Hooke (29)-(30) (elastic_law.hpp)
//     Kelvin-Voigt     tau_v = mu_s (1/lambda) d lambda / dt            (31)
//                      (one-sided second-order backward difference in time), or, once
//                      set_node_velocity() has been called, from the node velocities treated
//                      implicitly (see set_node_velocity): stable for large mu_s.
//   transverse shear   q = dm/dl,  m = E_B (kappa - kappa0)              (32)
//   curvature          periodic parametric cubic spline (PeriodicSpline), kappa0 = initial kappa.
// The load (27) f = -d/dl (tau t + q n) is the traction jump; the membrane pushes the fluid with
// -f = d/dl (tau t + q n). It is integrated over each node's share of the membrane, in
// conservative form: the force node i exerts on the fluid is
//   F_i = T_i - T_{i-1},   T_i = tau_i t_i + q_i n_i  on segment i (node i -> i+1),
// with q_i = (m_{i+1} - m_i) / l_i at the segment midpoint. Telescoping sums make the total
// force and (since sum_i l_i q_i = sum_i (m_{i+1} - m_i) = 0 and T_i's tension part is parallel
// to the segment) the total torque vanish exactly for any shape. pointwise_forces() evaluates
// (27) at the nodes with five-point arc-length derivatives, as the text does, for comparison.
// Orientation: counter-clockwise nodes, t along increasing node index, outward n = t turned
// clockwise, so dt/dl = -kappa n and a circle has kappa = +1/a.
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cstddef>
#include <vector>

#include "solver/membrane2d/elastic_law.hpp"
#include "solver/membrane2d/periodic_spline.hpp"

namespace capsule::membrane2d {

struct Moduli {
  double E_s = 0;   // shear elasticity modulus (30)
  double E_B = 0;   // bending modulus (32)
  double mu_s = 0;  // membrane viscosity (31)
};

class Membrane {
 public:
  // The given shape is the stress-free reference: l0 = its segment lengths, kappa0 = its curvature.
  Membrane(std::vector<double> xy, Moduli moduli, ElasticLaw law = ElasticLaw::hooke);

  std::size_t size() const { return n_; }
  std::vector<double>& positions() { return xy_; }  // flat (x0, y0, x1, y1, ...)
  const std::vector<double>& positions() const { return xy_; }
  const Moduli& moduli() const { return moduli_; }
  ElasticLaw law() const { return law_; }

  // Computes the forces the nodes exert on the fluid at the current positions. dt is the
  // time step for the viscous tension (31); advance_history = true (once per time step)
  // stores this step's stretches for the next backward difference.
  void compute_forces(double dt, bool advance_history = true);
  const std::vector<double>& forces() const { return force_; }

  // Implicit Kelvin-Voigt (31) for the immersed-boundary coupling. U: the node velocities
  // that moved the nodes onto the current positions (flat, 2 n), mobility m: how much a node
  // force F changes that node's interpolated velocity within the step (U ~ ... + m F).
  // compute_forces() then uses the strain rate of the predicted velocity
  //   P = U - m Fv_prev + m Fv,  Fv = -D^T W D P,  (D P)_i = t_i . (P_{i+1} - P_i),  W_i = mu_s / l_i,
  // i.e. tau_v,i = mu_s t_i . (P_{i+1} - P_i) / l_i = mu_s (1/lambda) dlambda/dt of the motion P,
  // solving (diag(l_i/mu_s) + m D D^T) tau_v = D (U - m Fv_prev) (cyclic tridiagonal). When the
  // viscous forces stop changing, P = U exactly (no bias in steady states); rigid motion gives
  // D U = 0, so tau_v = 0. With m = 0 it is the explicit rate of U. Until the first call the
  // backward difference of the stretches is used.
  void set_node_velocity(const std::vector<double>& U, double mobility);
  const std::vector<double>& viscous_tension() const { return tau_v_; }  // per segment, last call

  // Exact implicit Kelvin-Voigt (31) for the immersed-boundary coupling
  // (resolution.kelvin_voigt_step = "exact_mobility"). The node velocities of this step are
  // U = U_free + M F exactly (solver/ib/mobility.hpp: U_free from the fluid before the step, M
  // the step's IB mobility, scalar n x n acting on each component), F all node forces. With
  // F = F_other - D^T tau_v (F_other: Hooke and bending at the current shape) and
  // tau_v = W D U, W_i = mu_s / l_i, (D U)_i = t_i . (U_{i+1} - U_i):
  //   (diag(l_i / mu_s) + D M D^T) tau_v = D (U_free + M F_other),
  // symmetric positive definite, sparse (segments whose nodes' deltas overlap), solved by a
  // sparse LDL^T. The viscous tension is then mu_s (1/lambda) dlambda/dt of the motion the nodes
  // really make in the step: no assumed mobility, no lag. Needs mu_s > 0. Does not use or change
  // the state of set_node_velocity().
  void compute_forces_coupled(const std::vector<double>& U_free, const Eigen::SparseMatrix<double>& M,
                              bool advance_history = true);

  // State from the last compute_forces():
  const std::vector<double>& stretch() const { return lambda_; }          // per segment (29)
  const std::vector<double>& tension() const { return tau_; }             // per segment (28)
  const std::vector<double>& curvature() const { return spline_.curvatures(); }  // per node
  const std::vector<double>& reference_curvature() const { return kappa0_; }
  const std::vector<double>& bending_moment() const { return m_; }        // per node, m = E_B (kappa - kappa0)
  const std::vector<double>& reference_lengths() const { return l0_; }
  std::vector<double> outward_normals() const;  // per node, unit, from the spline tangent
                                                // of the last compute_forces() / refit()
  void refit() { fit_geometry(); }              // after moving positions() by hand

  // (27) at the nodes with five-point non-uniform arc-length derivatives, times each node's
  // share of arc length (l_{i-1} + l_i)/2: the text's discretisation, not conservative.
  std::vector<double> pointwise_forces() const;

  // Restart points (solver/run/checkpoint.hpp): the positions and the history a later
  // compute_forces() reads (stretches one and two steps back, the implicit viscous state).
  // The reference (l0, kappa0) follows from the scene and is rebuilt, not restored.
  struct History {
    std::vector<double> xy, lambda_prev1, lambda_prev2, U, Fv_prev;
    int steps = 0;
    bool implicit = false;
    double mobility = 0;
  };
  History history() const;
  void restore(const History& h);  // throws std::invalid_argument on a size mismatch

 private:
  void fit_geometry();
  void assemble_forces();  // m, q and the node forces from tau_ at the current geometry

  std::size_t n_;
  std::vector<double> xy_;
  Moduli moduli_;
  ElasticLaw law_;
  std::vector<double> l0_, kappa0_;
  PeriodicSpline spline_;
  std::vector<double> l_, lambda_, tau_, m_, q_, force_;
  std::vector<double> lambda_prev1_, lambda_prev2_;  // stretches one and two steps back
  int history_ = 0;                                   // how many of them exist
  // implicit Kelvin-Voigt state
  bool implicit_ = false;
  double mobility_ = 0;
  std::vector<double> U_, Fv_prev_, Fv_, tau_v_, off_, diag_, rx_, ry_, work_, z_;
  std::vector<double> T_;  // segment tension vectors (assemble_forces)
  // exact coupled Kelvin-Voigt (compute_forces_coupled)
  std::vector<double> V_, tangent_;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> A_;
  // The sparse LDL^T of A, its ordering and symbolic analysis kept while A's pattern is unchanged
  // (the overlaps change only when nodes move across a lattice cell). A copy starts afresh.
  struct Factor {
    Factor() = default;
    Factor(const Factor&) {}
    Factor& operator=(const Factor&) { reset(); return *this; }
    void reset() { outer.clear(), inner.clear(); }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> ldlt;
    std::vector<int> outer, inner;  // the pattern ldlt was analysed for
  };
  Factor factor_;
};

}  // namespace capsule::membrane2d
