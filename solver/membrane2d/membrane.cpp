#include "solver/membrane2d/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/membrane2d/arc_derivative.hpp"

namespace capsule::membrane2d {

Membrane::Membrane(std::vector<double> xy, Moduli moduli, ElasticLaw law)
    : n_(xy.size() / 2), xy_(std::move(xy)), moduli_(moduli), law_(law) {
  if (n_ < 5) throw std::invalid_argument("Membrane: need at least 5 nodes");
  l_.assign(n_, 0.0);
  fit_geometry();
  l0_ = l_;
  kappa0_ = spline_.curvatures();
  lambda_.assign(n_, 1.0);
  tau_.assign(n_, 0.0);
  m_.assign(n_, 0.0);
  q_.assign(n_, 0.0);
  force_.assign(2 * n_, 0.0);
  tau_v_.assign(n_, 0.0);
  Fv_prev_.assign(2 * n_, 0.0);
  Fv_.assign(2 * n_, 0.0);
}

void Membrane::set_node_velocity(const std::vector<double>& U, double mobility) {
  if (U.size() != 2 * n_) throw std::invalid_argument("Membrane::set_node_velocity: wrong size");
  if (!(mobility >= 0.0)) throw std::invalid_argument("Membrane::set_node_velocity: mobility < 0");
  U_ = U;
  mobility_ = mobility;
  implicit_ = true;
}

Membrane::History Membrane::history() const {
  return {xy_, lambda_prev1_, lambda_prev2_, U_, Fv_prev_, history_, implicit_, mobility_};
}

void Membrane::restore(const History& h) {
  const auto fits = [&](const std::vector<double>& v, std::size_t n) { return v.empty() || v.size() == n; };
  if (h.xy.size() != 2 * n_ || !fits(h.lambda_prev1, n_) || !fits(h.lambda_prev2, n_) || !fits(h.U, 2 * n_) ||
      h.Fv_prev.size() != 2 * n_)
    throw std::invalid_argument("Membrane::restore: the saved history does not fit this membrane");
  xy_ = h.xy;
  lambda_prev1_ = h.lambda_prev1;
  lambda_prev2_ = h.lambda_prev2;
  U_ = h.U;
  Fv_prev_ = h.Fv_prev;
  history_ = h.steps;
  implicit_ = h.implicit;
  mobility_ = h.mobility;
  fit_geometry();
}

void Membrane::fit_geometry() {
  for (std::size_t i = 0; i < n_; ++i) {
    const std::size_t j = (i + 1) % n_;
    l_[i] = std::hypot(xy_[2 * j] - xy_[2 * i], xy_[2 * j + 1] - xy_[2 * i + 1]);
  }
  spline_.fit(xy_);
}

void Membrane::compute_forces(double dt, bool advance_history) {
  fit_geometry();
  for (std::size_t i = 0; i < n_; ++i) lambda_[i] = l_[i] / l0_[i];  // (29)
  if (implicit_ && moduli_.mu_s > 0.0) {
    // (31) from the predicted node velocities (see set_node_velocity): cyclic tridiagonal solve
    // (diag(l/mu_s) + m D D^T) tau_v = D (U - m Fv_prev), (D D^T)_{i,i} = 2, (D D^T)_{i,i+1} = -t_i.t_{i+1}.
    const double m = mobility_;
    off_.resize(n_), diag_.resize(n_), rx_.resize(n_), ry_.assign(n_, 0.0);
    for (std::size_t i = 0; i < n_; ++i) {
      const std::size_t j = (i + 1) % n_, k = (i + 2) % n_;
      const double tx = (xy_[2 * j] - xy_[2 * i]) / l_[i], ty = (xy_[2 * j + 1] - xy_[2 * i + 1]) / l_[i];
      const double sx = (xy_[2 * k] - xy_[2 * j]) / l_[j], sy = (xy_[2 * k + 1] - xy_[2 * j + 1]) / l_[j];
      const double bx = (U_[2 * j] - m * Fv_prev_[2 * j]) - (U_[2 * i] - m * Fv_prev_[2 * i]);
      const double by = (U_[2 * j + 1] - m * Fv_prev_[2 * j + 1]) - (U_[2 * i + 1] - m * Fv_prev_[2 * i + 1]);
      rx_[i] = tx * bx + ty * by;
      diag_[i] = l_[i] / moduli_.mu_s + 2.0 * m;
      off_[i] = -m * (tx * sx + ty * sy);
    }
    solve_cyclic_tridiagonal_symmetric(off_, diag_, rx_, ry_, work_, z_);
    visit_law(law_, moduli_.E_s, [&](const auto& law) {
      for (std::size_t i = 0; i < n_; ++i) {
        tau_v_[i] = rx_[i];
        tau_[i] = law.tension(lambda_[i]) + tau_v_[i];  // (28), (30), (31)
      }
    });
    // the viscous node forces, for the next prediction
    for (std::size_t i = 0; i < n_; ++i) {
      const std::size_t j = (i + 1) % n_, k = (i + n_ - 1) % n_;
      const double tx = (xy_[2 * j] - xy_[2 * i]) / l_[i], ty = (xy_[2 * j + 1] - xy_[2 * i + 1]) / l_[i];
      const double px = (xy_[2 * i] - xy_[2 * k]) / l_[k], py = (xy_[2 * i + 1] - xy_[2 * k + 1]) / l_[k];
      Fv_[2 * i] = tau_v_[i] * tx - tau_v_[k] * px;
      Fv_[2 * i + 1] = tau_v_[i] * ty - tau_v_[k] * py;
    }
  } else {
    // (31): d lambda / dt by the one-sided second-order difference (3 l - 4 l1 + l2) / (2 dt),
    // first order on the second step, zero on the first (the membrane starts at rest).
    visit_law(law_, moduli_.E_s, [&](const auto& law) {
      for (std::size_t i = 0; i < n_; ++i) {
        double rate = 0.0;
        if (history_ >= 2)
          rate = (3.0 * lambda_[i] - 4.0 * lambda_prev1_[i] + lambda_prev2_[i]) / (2.0 * dt);
        else if (history_ == 1)
          rate = (lambda_[i] - lambda_prev1_[i]) / dt;
        tau_[i] = law.tension(lambda_[i]) + moduli_.mu_s * rate / lambda_[i];  // (28), (30), (31)
      }
      for (std::size_t i = 0; i < n_; ++i) tau_v_[i] = tau_[i] - law.tension(lambda_[i]);
    });
  }
  if (advance_history) {
    lambda_prev2_.swap(lambda_prev1_);
    lambda_prev1_ = lambda_;
    history_ = std::min(history_ + 1, 2);
    if (implicit_) Fv_prev_ = Fv_;
  }
  assemble_forces();
}

void Membrane::assemble_forces() {
  const auto& kappa = spline_.curvatures();
  for (std::size_t i = 0; i < n_; ++i) m_[i] = moduli_.E_B * (kappa[i] - kappa0_[i]);  // (32)
  // Segment tension vectors T_i = tau_i t_i + q_i n_i, q_i = (m_{i+1} - m_i) / l_i (32).
  std::vector<double>& T = T_;
  T.resize(2 * n_);
  for (std::size_t i = 0; i < n_; ++i) {
    const std::size_t j = (i + 1) % n_;
    const double tx = (xy_[2 * j] - xy_[2 * i]) / l_[i], ty = (xy_[2 * j + 1] - xy_[2 * i + 1]) / l_[i];
    q_[i] = (m_[j] - m_[i]) / l_[i];
    // n = (ty, -tx): outward for counter-clockwise nodes
    T[2 * i] = tau_[i] * tx + q_[i] * ty;
    T[2 * i + 1] = tau_[i] * ty - q_[i] * tx;
  }
  // F_i = T_i - T_{i-1}: (27) integrated over node i's share of the membrane, sign for the fluid.
  for (std::size_t i = 0; i < n_; ++i) {
    const std::size_t k = (i + n_ - 1) % n_;
    force_[2 * i] = T[2 * i] - T[2 * k];
    force_[2 * i + 1] = T[2 * i + 1] - T[2 * k + 1];
  }
}

void Membrane::compute_forces_coupled(const std::vector<double>& U_free, const Eigen::SparseMatrix<double>& M,
                                      bool advance_history) {
  if (U_free.size() != 2 * n_ || M.rows() != static_cast<Eigen::Index>(n_) || M.cols() != static_cast<Eigen::Index>(n_))
    throw std::invalid_argument("Membrane::compute_forces_coupled: U_free or M does not fit the membrane");
  if (!(moduli_.mu_s > 0.0)) throw std::invalid_argument("Membrane::compute_forces_coupled: needs mu_s > 0");
  fit_geometry();
  for (std::size_t i = 0; i < n_; ++i) lambda_[i] = l_[i] / l0_[i];  // (29)
  // 1. The other forces (elastic (30) and bending (32)) at the current shape: tau_v = 0.
  visit_law(law_, moduli_.E_s, [&](const auto& law) {
    for (std::size_t i = 0; i < n_; ++i) tau_[i] = law.tension(lambda_[i]);
  });
  assemble_forces();
  // 2. The velocity those forces alone would give, V = U_free + M F_other, and its strain rate.
  V_.assign(U_free.begin(), U_free.end());
  for (Eigen::Index k = 0; k < M.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it) {
      V_[2 * it.row()] += it.value() * force_[2 * it.col()];
      V_[2 * it.row() + 1] += it.value() * force_[2 * it.col() + 1];
    }
  tangent_.resize(2 * n_);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n_));
  for (std::size_t i = 0; i < n_; ++i) {
    const std::size_t j = (i + 1) % n_;
    const double tx = (xy_[2 * j] - xy_[2 * i]) / l_[i], ty = (xy_[2 * j + 1] - xy_[2 * i + 1]) / l_[i];
    tangent_[2 * i] = tx, tangent_[2 * i + 1] = ty;
    b[static_cast<Eigen::Index>(i)] = tx * (V_[2 * j] - V_[2 * i]) + ty * (V_[2 * j + 1] - V_[2 * i + 1]);
  }
  // 3. A = diag(l/mu_s) + D M D^T, upper triangle. D's row i (segment i, nodes i -> i+1) is -t_i at
  //    node i and +t_i at node i+1, so node c enters segments c - 1 (sign +) and c (sign -):
  //    A_ik = sum over ordered node pairs (c, d) of s_ic s_kd (t_i . t_k) M_cd.
  triplets_.clear();
  for (std::size_t i = 0; i < n_; ++i)
    triplets_.emplace_back(static_cast<int>(i), static_cast<int>(i), l_[i] / moduli_.mu_s);
  for (Eigen::Index k = 0; k < M.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it) {
      const std::size_t c = static_cast<std::size_t>(it.row()), d = static_cast<std::size_t>(it.col());
      const std::size_t seg_c[2] = {c == 0 ? n_ - 1 : c - 1, c}, seg_d[2] = {d == 0 ? n_ - 1 : d - 1, d};
      for (int p = 0; p < 2; ++p)
        for (int q = 0; q < 2; ++q) {
          const std::size_t i = seg_c[p], j = seg_d[q];
          if (i > j) continue;  // the mirrored ordered pair (d, c) brings it to the upper triangle
          const double tt = tangent_[2 * i] * tangent_[2 * j] + tangent_[2 * i + 1] * tangent_[2 * j + 1];
          triplets_.emplace_back(static_cast<int>(i), static_cast<int>(j), (p == q ? tt : -tt) * it.value());
        }
    }
  // A pattern that rarely changes as the nodes move across lattice cells (a change costs a new
  // ordering and symbolic analysis): the cyclic band of segments up to `band` apart along the
  // chain, the widest coupling within a quarter of the chain rounded up to the next multiple of
  // 4 (a function of this step's couplings only, so a resumed run solves with the same pattern
  // and stays bitwise); couplings across the capsule (a thin or folded shape) add their own.
  std::size_t need = 0;
  for (const auto& t : triplets_) {
    const std::size_t gap = static_cast<std::size_t>(t.col() - t.row()), chain = std::min(gap, n_ - gap);
    if (chain <= n_ / 4) need = std::max(need, chain);
  }
  const std::size_t band = std::min((need / 4 + 1) * 4, n_ / 2);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t r = 1; r <= band; ++r) {
      const std::size_t j = (i + r) % n_;
      triplets_.emplace_back(static_cast<int>(std::min(i, j)), static_cast<int>(std::max(i, j)), 0.0);
    }
  A_.resize(static_cast<Eigen::Index>(n_), static_cast<Eigen::Index>(n_));
  A_.setFromTriplets(triplets_.begin(), triplets_.end());
  A_.makeCompressed();
  // 4. tau_v = A^-1 D V: mu_s t_i . (U_{i+1} - U_i) / l_i of the velocities U = U_free + M F the
  //    step will give (F including the viscous forces -D^T tau_v themselves).
  const auto same = [](const std::vector<int>& v, const int* p, std::size_t size) {
    return v.size() == size && std::equal(v.begin(), v.end(), p);
  };
  const std::size_t nnz = static_cast<std::size_t>(A_.nonZeros());
  if (!same(factor_.outer, A_.outerIndexPtr(), n_ + 1) || !same(factor_.inner, A_.innerIndexPtr(), nnz)) {
    factor_.ldlt.analyzePattern(A_);
    factor_.outer.assign(A_.outerIndexPtr(), A_.outerIndexPtr() + n_ + 1);
    factor_.inner.assign(A_.innerIndexPtr(), A_.innerIndexPtr() + nnz);
  }
  factor_.ldlt.factorize(A_);
  if (factor_.ldlt.info() != Eigen::Success)
    throw std::runtime_error("Membrane::compute_forces_coupled: the viscous system is not positive definite");
  const Eigen::VectorXd tv = factor_.ldlt.solve(b);
  for (std::size_t i = 0; i < n_; ++i) {
    tau_v_[i] = tv[static_cast<Eigen::Index>(i)];
    tau_[i] += tau_v_[i];  // (28), (30), (31)
  }
  if (advance_history) {
    lambda_prev2_.swap(lambda_prev1_);
    lambda_prev1_ = lambda_;
    history_ = std::min(history_ + 1, 2);
  }
  assemble_forces();
}

std::vector<double> Membrane::outward_normals() const {
  std::vector<double> n(2 * n_);
  for (std::size_t i = 0; i < n_; ++i) {
    n[2 * i] = spline_.tangent_y(static_cast<int>(i));
    n[2 * i + 1] = -spline_.tangent_x(static_cast<int>(i));
  }
  return n;
}

std::vector<double> Membrane::pointwise_forces() const {
  const int n = static_cast<int>(n_);
  auto wrap = [n](int i) { return (i % n + n) % n; };
  // node arc-length coordinates (unwrapped around node i by summing lengths)
  auto stencil_s = [&](int i, double s[5]) {
    s[2] = 0.0;
    s[3] = l_[wrap(i)];
    s[4] = s[3] + l_[wrap(i + 1)];
    s[1] = -l_[wrap(i - 1)];
    s[0] = s[1] - l_[wrap(i - 2)];
  };
  auto d5 = [&](const std::vector<double>& f, int i) {
    double s[5], v[5];
    stencil_s(i, s);
    for (int k = 0; k < 5; ++k) v[k] = f[wrap(i - 2 + k)];
    return five_point_derivative(s, v);
  };
  const auto& kappa = spline_.curvatures();
  std::vector<double> tau_node(n), q_node(n), dtau(n), dq(n);
  for (int i = 0; i < n; ++i) tau_node[i] = 0.5 * (tau_[wrap(i - 1)] + tau_[i]);
  for (int i = 0; i < n; ++i) q_node[i] = d5(m_, i);
  for (int i = 0; i < n; ++i) {
    dtau[i] = d5(tau_node, i);
    dq[i] = d5(q_node, i);
  }
  std::vector<double> F(2 * n_);
  for (int i = 0; i < n; ++i) {
    const double tx = spline_.tangent_x(i), ty = spline_.tangent_y(i);
    const double nx = ty, ny = -tx;
    const double fn = kappa[i] * tau_node[i] - dq[i];      // (27) normal part
    const double ft = -(dtau[i] + kappa[i] * q_node[i]);  // (27) tangential part
    const double share = 0.5 * (l_[wrap(i - 1)] + l_[i]);
    F[2 * i] = -(fn * nx + ft * tx) * share;  // the fluid receives -f
    F[2 * i + 1] = -(fn * ny + ft * ty) * share;
  }
  return F;
}

}  // namespace capsule::membrane2d
