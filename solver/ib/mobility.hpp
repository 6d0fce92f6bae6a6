#pragma once
// The immersed boundary's mobility within one step: how the node velocity the IB interpolates
// after a fluid step depends on the node forces spread into that step (Sec. 2.3 with the
// forcing (22)). With the force density F_grid = S F spread by (21), the fluid's
// u(n) = (j(n) + F_grid/2) / rho(n) (22, solver/lbm/fluid.hpp, its time levels) and U = S^T u (19),
//
//   U = U_free + M F,   U_free,c = sum_x phi_c(x) j(x) / rho(x),
//                       M_cd     = sum_x phi_c(x) phi_d(x) / (2 rho(x)),
//
// exactly (up to rounding), where phi_c(x) = delta(X_c - x) is node c's delta weight at lattice
// node x and rho, j = sum f c are the moments of the populations before the step
// (lbm::Fluid::moments). M acts on every Cartesian component alike (a scalar n x n matrix); it
// is symmetric positive semi-definite and sparse: two nodes interact within the step only if
// their delta supports overlap. The rest of the fluid's response to F (the other half of the
// momentum, streamed, and the flow it drives later) reaches the nodes through U_free of the
// later steps. The 2D driver uses this split for its exact implicit Kelvin-Voigt step
// (resolution.kelvin_voigt_step = "exact_mobility", solver/membrane2d/membrane.hpp).
//
// 2D (the 3D membrane's viscosity is the standard linear solid, explicit). Cost per step: 16 n
// moments and weights, the overlapping pairs found through a cell list, 16 products per pair.
#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "solver/ib/delta.hpp"
#include "solver/ib/grid.hpp"
#include "solver/ib/interpolation.hpp"

namespace capsule::ib {

class StepMobility2D {
 public:
  // moments(lattice_index) -> std::array<double, 4> {rho, j_x, j_y, j_z} (lbm::Fluid::moments).
  template <class Moments>
  void assemble(const Grid& grid, const double* X, std::size_t n, Delta delta, Moments&& moments) {
    if (delta_width(delta) != 4) throw std::invalid_argument("StepMobility2D: 4-point deltas only");
    if (grid.nx < 8) throw std::invalid_argument("StepMobility2D: needs nx >= 8 (one periodic image per pair)");
    nx_ = grid.nx, ny_ = grid.ny;
    if (xwrap_.size() != static_cast<std::size_t>(nx_ + 2 * kPad)) {
      xwrap_.resize(nx_ + 2 * kPad);
      for (int i = -kPad; i < nx_ + kPad; ++i) xwrap_[i + kPad] = wrap(i, nx_);
    }
    if (stamp_.size() != grid.size()) {
      stamp_.assign(grid.size(), 0u);
      h_.assign(grid.size(), 0.0);
      v_.assign(2 * grid.size(), 0.0);
      epoch_ = 0;
    }
    if (++epoch_ == 0) {  // wrapped: forget every stamp
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      epoch_ = 1;
    }
    st_.resize(n);
    U_free_.assign(2 * n, 0.0);
    for (std::size_t c = 0; c < n; ++c) {
      Stencil& s = st_[c];
      const DeltaStencil1D sx = delta_stencil(X[2 * c], delta), sy = delta_stencil(X[2 * c + 1], delta);
      s.fx = wrap(sx.first, nx_), s.fy = sy.first;  // x origin in [0, nx): the tables below reach nx + 6
      for (int m = 0; m < 4; ++m) {
        s.wx[m] = sx.w[m];
        const int j = sy.first + m;
        s.wy[m] = (j < 0 || j >= ny_) ? 0.0 : sy.w[m];  // rows beyond a wall are dropped, as in (19), (21)
      }
      double ux = 0.0, uy = 0.0;
      for (int b = 0; b < 4; ++b) {
        if (s.wy[b] == 0.0) continue;
        const std::size_t row = static_cast<std::size_t>(nx_) * (s.fy + b);
        for (int m = 0; m < 4; ++m) {
          const std::size_t node = row + xw(s.fx + m);
          if (stamp_[node] != epoch_) {
            stamp_[node] = epoch_;
            const std::array<double, 4> mom = moments(node);
            const double inv_rho = 1.0 / mom[0];
            h_[node] = 0.5 * inv_rho;
            v_[2 * node] = mom[1] * inv_rho;
            v_[2 * node + 1] = mom[2] * inv_rho;
          }
          const double w = s.wx[m] * s.wy[b];
          ux += w * v_[2 * node];
          uy += w * v_[2 * node + 1];
        }
      }
      U_free_[2 * c] = ux, U_free_[2 * c + 1] = uy;
    }
    // Pairs with overlapping supports (stencil origins less than 4 apart along both axes),
    // through a cell list on the stencil origins.
    const int rows = ny_ + 8;  // origins lie in [-3, ny) along y
    if (head_.size() != static_cast<std::size_t>(rows) * nx_) head_.assign(static_cast<std::size_t>(rows) * nx_, -1);
    next_.assign(n, -1);
    auto cell = [&](int fx, int fy) { return static_cast<std::size_t>(fy + 4) * nx_ + xw(fx); };
    for (std::size_t c = 0; c < n; ++c) {
      const std::size_t k = cell(st_[c].fx, st_[c].fy);
      next_[c] = head_[k];
      head_[k] = static_cast<int>(c);
    }
    triplets_.clear();
    for (std::size_t c = 0; c < n; ++c) {
      const Stencil& a = st_[c];
      for (int dy = -3; dy <= 3; ++dy) {
        const int fy = a.fy + dy;
        if (fy + 4 < 0 || fy + 4 >= rows) continue;
        for (int dx = -3; dx <= 3; ++dx)
          for (int d = head_[cell(a.fx + dx, fy)]; d >= 0; d = next_[d]) {
            if (static_cast<std::size_t>(d) < c) continue;
            const double m = pair(a, st_[d], dx, dy);
            if (m == 0.0) continue;
            triplets_.emplace_back(static_cast<int>(c), d, m);
            if (static_cast<std::size_t>(d) != c) triplets_.emplace_back(d, static_cast<int>(c), m);
          }
      }
    }
    for (std::size_t c = 0; c < n; ++c) head_[cell(st_[c].fx, st_[c].fy)] = -1;
    M_.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    M_.setFromTriplets(triplets_.begin(), triplets_.end());
  }

  // The node velocities without this step's force (2 n, node-major).
  const std::vector<double>& free_velocity() const { return U_free_; }
  // M, n x n, symmetric, acting on each component.
  const Eigen::SparseMatrix<double>& matrix() const { return M_; }

  // U_free + M F: the velocities the IB interpolates after the step that spreads the forces F.
  std::vector<double> predict(const double* F) const {
    std::vector<double> U = U_free_;
    for (Eigen::Index k = 0; k < M_.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(M_, k); it; ++it)
        for (int a = 0; a < 2; ++a) U[2 * it.row() + a] += it.value() * F[2 * it.col() + a];
    return U;
  }

 private:
  struct Stencil {
    int fx = 0, fy = 0;
    double wx[4] = {}, wy[4] = {};
  };
  // sum over the common support of phi_a phi_b / (2 rho); b's origin is a's plus (dx, dy), |dx|, |dy| < 4
  // (dx as found in the cell list: the periodic image that overlaps).
  double pair(const Stencil& a, const Stencil& b, int dx, int dy) const {
    double m = 0.0;
    for (int q = std::max(0, dy); q < std::min(4, 4 + dy); ++q) {  // q: a's row offset, q - dy: b's
      const double wy = a.wy[q] * b.wy[q - dy];
      if (wy == 0.0) continue;
      const std::size_t row = static_cast<std::size_t>(nx_) * (a.fy + q);
      for (int p = std::max(0, dx); p < std::min(4, 4 + dx); ++p)
        m += a.wx[p] * b.wx[p - dx] * wy * h_[row + xw(a.fx + p)];
    }
    return m;
  }

  // x wrapped into [0, nx) by table for x in [-kPad, nx + kPad): origins lie in [0, nx), cells are
  // searched up to 3 either side, support nodes reach 3 beyond the origin
  static constexpr int kPad = 8;
  int xw(int x) const { return xwrap_[x + kPad]; }
  std::vector<int> xwrap_;
  int nx_ = 0, ny_ = 0;
  std::vector<unsigned> stamp_;
  unsigned epoch_ = 0;
  std::vector<double> h_, v_, U_free_;  // per lattice node: 1/(2 rho), j/rho
  std::vector<Stencil> st_;
  std::vector<int> head_, next_;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> M_;
};

}  // namespace capsule::ib
