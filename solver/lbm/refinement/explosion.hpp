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

namespace capsule::lbm::refinement {

// Taylor coefficients of population i around ring cell R (coarse spacings): per axis the first
// derivative g_a and the second h_a, central where both neighbours are uncovered channel cells,
// else one-sided away from the block over two cells (exact for a quadratic field, as f* is in a
// linear shear: the equilibrium (5) holds u^2). Mixed derivatives are left out.
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

template <class L>
Taylor coarse_taylor(const RefinedBlock<L::D>& block, const double* coarse, const std::array<int, 3>& R, int i) {
  Taylor t;
  const double f0 = coarse[block.coarse_index(R[0], R[1], R[2]) * L::Q + i];
  for (int a = 0; a < L::D; ++a) {
    // f at R + k e_a for k = -2, -1, 1, 2 where usable.
    double f[5] = {0.0, 0.0, f0, 0.0, 0.0};
    bool ok[5] = {false, false, true, false, false};
    for (int k = -2; k <= 2; ++k) {
      if (k == 0) continue;
      std::array<int, 3> N = R;
      N[a] += k;
      if (a != 1) N[a] = (N[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
      ok[k + 2] = N[a] >= 0 && N[a] < block.coarse_n(a) && !block.covered(N);
      if (ok[k + 2]) f[k + 2] = coarse[block.coarse_index(N[0], N[1], N[2]) * L::Q + i];
    }
    if (ok[1] && ok[3]) {
      t.g[a] = 0.5 * (f[3] - f[1]);
      t.h[a] = f[3] - 2.0 * f0 + f[1];
    } else if (ok[3] && ok[4]) {
      t.g[a] = 0.5 * (-3.0 * f0 + 4.0 * f[3] - f[4]);
      t.h[a] = f0 - 2.0 * f[3] + f[4];
    } else if (ok[1] && ok[0]) {
      t.g[a] = 0.5 * (3.0 * f0 - 4.0 * f[1] + f[0]);
      t.h[a] = f0 - 2.0 * f[1] + f[0];
    }
  }
  return t;
}

// Is the coarse cell R + c_i (wrapped) in the fine lattice?
template <class L>
bool feeds_fine(const RefinedBlock<L::D>& block, const std::array<int, 3>& R, int i) {
  std::array<int, 3> S = R;
  for (int a = 0; a < L::D; ++a) {
    S[a] += L::c[i][a];
    if (a != 1) S[a] = (S[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
  }
  return S[1] >= 0 && S[1] < block.coarse_n(1) && block.in_fine_lattice(S);
}

// coarse: Q populations per coarse cell (post-collision on uncovered cells); fine: Q per fine
// cell. Returns the mass (fine cell volumes) the fed channels carry beyond the coarse share.
template <class L>
double explode(const RefinedBlock<L::D>& block, const double* coarse, double* fine) {
  constexpr int Q = L::Q, D = L::D;
  const int children = 1 << D;
  const int nzc = D == 3 ? block.fine_n(2) / 2 : 1;
  const int nyc = block.fine_n(1) / 2, nxc = block.fine_n(0) / 2;
  const std::array<int, 3> base = block.parent({0, 0, 0});
  const long cells = long(nxc) * nyc * nzc;
  std::vector<double> excess(std::size_t(cells), 0.0);
#pragma omp parallel for schedule(static)
  for (long r = 0; r < cells; ++r) {
    std::array<int, 3> R{base[0] + int(r % nxc), base[1] + int((r / nxc) % nyc), base[2] + int(r / (long(nxc) * nyc))};
    for (int a = 0; a < D; ++a)
      if (block.spans(a)) R[a] = (R[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
    if (!block.ring(R)) continue;
    const std::size_t cR = block.coarse_index(R[0], R[1], R[2]);
    const std::array<int, 3> f0 = block.first_child(R);
    for (int i = 0; i < Q; ++i) {
      const double fR = coarse[cR * Q + i];
      const Taylor t = coarse_taylor<L>(block, coarse, R, i);
      double sum = 0.0;
      for (int k = 0; k < children; ++k) {
        std::array<int, 3> o = f0;
        for (int a = 0; a < D; ++a) o[a] += (k >> a) & 1;
        std::array<int, 3> o1 = o, o2 = o;
        for (int a = 0; a < D; ++a) {
          o1[a] += L::c[i][a];
          o2[a] += 2 * L::c[i][a];
        }
        double shift = 0.0;
        if (block.wrap_fine(o1) && block.fine_in_block(o1)) shift = -0.25;
        else if (block.wrap_fine(o2) && block.fine_in_block(o2)) shift = 0.25;
        double e[3] = {0.0, 0.0, 0.0};
        for (int a = 0; a < D; ++a) e[a] = 0.5 * (((k >> a) & 1) - 0.5) + shift * L::c[i][a];
        const double v = fR + t.change(e);
        fine[block.fine_index(o[0], o[1], o[2]) * Q + i] = v;
        sum += v;
      }
      if (feeds_fine<L>(block, R, i)) excess[std::size_t(r)] += sum - children * fR;
    }
  }
  double total = 0.0;
  for (double e : excess) total += e;
  return total;
}

}  // namespace capsule::lbm::refinement
