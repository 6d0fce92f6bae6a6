#pragma once
// Coarse-to-fine transfer ("explosion", Rohde et al. 2006; docs/guide/refinement.md): the
// post-collision populations f*_i(R) of every ring cell R are written to its 2^D fine ghost
// children, once per coarse step; the ghost layer then streams them, uncollided, over the two
// fine sub-steps, so a coarse population travels one coarse spacing in one coarse time step as
// it does on the coarse lattice.
//
// Each child o of R gets the Taylor reconstruction
//   f_i(o) = f*_i(R) + sum_a [g_ia d_a + h_ia d_a^2 / 2],
// g_ia, h_ia the coarse first and second derivatives of f*_i (coarse_taylor), and, in coarse
// spacings,
//   d(o, i) = x(o) - x(R) - c_i/4   if o + c_i is a block cell (it enters at the first sub-step),
//           = x(o) - x(R) + c_i/4   if o + c_i is not, but o + 2 c_i is (it enters at the second),
//           = x(o) - x(R)           otherwise (it stays in the ring).
// The shifts +-c_i/4 (half a fine spacing) give the fine lattice its own post-collision
// populations in a flow linear in space: a post-collision population is the equilibrium taken
// (tau - 1) dt c_i upstream, and (tau_f - 1) dt_f = (tau_c - 1) dt_c + dt_f/2 when
// tau_f - 1/2 = 2 (tau_c - 1/2), so f*_fine(x) = f*_coarse(x - c_i dt_f/2).
// Where a channel (R, i) feeds the fine lattice (R + c_i in it), its children carry
// more mass than the coarse lattice gives away (2^D g_i . <d> and the curvature terms; <d>, the
// children mean, is zero along a plane face, not at the block's edges and corners); explode
// returns the sum, which the fluid gives back (refined_fluid.hpp).
#include <array>
#include <cstddef>
#include <vector>

#include "solver/lbm/refinement/refined_block.hpp"
#include "solver/lbm/refinement/ring_plan.hpp"

namespace capsule::lbm::refinement {

// Taylor coefficients of population i around ring cell R (coarse spacings): per axis the first
// derivative g_a and the second h_a (exact for a quadratic field, as f* is in a linear shear:
// the equilibrium (5) holds u^2). Mixed derivatives are left out.
struct Taylor {
  double g[3] = {0.0, 0.0, 0.0};
  double h[3] = {0.0, 0.0, 0.0};
  // f(R + e) - f(R)
  double change(const double (&e)[3]) const {
    double v = 0.0;
    for (int a = 0; a < 3; ++a) v += e[a] * (g[a] + 0.5 * h[a] * e[a]);
    return v;
  }
};

// The coefficients about ring cell c of population i, f the coarse populations of direction i
// (RingPlan's stencil: central where both neighbours are uncovered channel cells, else
// one-sided away from the block over two cells).
template <class L, class T>
Taylor taylor_at(const typename RingPlan<L>::Cell& c, const T* f) {
  using Plan = RingPlan<L>;
  Taylor t;
  const double f0 = f[c.coarse];
  for (int a = 0; a < L::D; ++a) {
    const auto& s = c.axis[std::size_t(a)];
    const double f1 = f[s.m1], f2 = f[s.m2];
    switch (s.kind) {
      case Plan::central:  // m1 = R - 1, m2 = R + 1
        t.g[a] = 0.5 * (f2 - f1);
        t.h[a] = f2 - 2.0 * f0 + f1;
        break;
      case Plan::forward:  // m1 = R + 1, m2 = R + 2
        t.g[a] = 0.5 * (-3.0 * f0 + 4.0 * f1 - f2);
        t.h[a] = f0 - 2.0 * f1 + f2;
        break;
      case Plan::backward:  // m1 = R - 1, m2 = R - 2
        t.g[a] = 0.5 * (3.0 * f0 - 4.0 * f1 + f2);
        t.h[a] = f0 - 2.0 * f1 + f2;
        break;
      case Plan::none:
        break;
    }
  }
  return t;
}

// coarse: the post-collision populations (shifted, by direction: RefinedBlock::coarse_at; T
// double or float, the arithmetic double);
// fine gets the ghost children. `taylor` keeps each (ring cell, i)'s coefficients for the
// coalescence of the same coarse step (coalescence.hpp), which reads the same coarse values.
// Returns the mass (fine cell volumes) the fed channels carry beyond the coarse share.
template <class L, class T>
double explode(const RefinedBlock<L::D>& block, const RingPlan<L>& plan, const T* coarse, T* fine,
               std::vector<Taylor>& taylor) {
  constexpr int Q = L::Q, D = L::D, children = RingPlan<L>::children;
  const std::size_t N = block.coarse_size(), F = block.fine_size();
  const long cells = long(plan.cells.size());
  taylor.resize(std::size_t(cells) * Q);
  std::vector<double> excess(std::size_t(cells), 0.0);
#pragma omp parallel for schedule(static)
  for (long r = 0; r < cells; ++r) {
    const auto& c = plan.cells[std::size_t(r)];
    for (int i = 0; i < Q; ++i) {
      const T* fi = coarse + std::size_t(i) * N;
      const double fR = fi[c.coarse];
      const std::size_t ri = std::size_t(r) * Q + std::size_t(i);
      const Taylor t = taylor_at<L>(c, fi);
      taylor[ri] = t;
      double sum = 0.0;
      for (int k = 0; k < children; ++k) {
        const double shift = 0.25 * plan.explode_shift[ri * children + std::size_t(k)];
        double e[3] = {0.0, 0.0, 0.0};
        for (int a = 0; a < D; ++a) e[a] = 0.5 * (((k >> a) & 1) - 0.5) + shift * L::c[i][a];
        const T v = T(fR + t.change(e));
        fine[std::size_t(i) * F + c.child[std::size_t(k)]] = v;
        sum += double(v);
      }
      if (plan.feeds[ri]) excess[std::size_t(r)] += sum - children * fR;
    }
  }
  double total = 0.0;
  for (double e : excess) total += e;
  return total;
}

}  // namespace capsule::lbm::refinement
