#pragma once
// Coarse-to-fine transfer ("explosion", Rohde et al. 2006; docs/guide/refinement.md): the
// post-collision populations f*_i(R) of every ring cell R are written to its 2^D fine ghost
// children, once per coarse step; the ghost layer then streams them, uncollided, over the two
// fine sub-steps, so a coarse population travels one coarse spacing in one coarse time step as
// it would on the coarse lattice.
//
// Each child o of R gets the linear reconstruction
//   f_i(o) = f*_i(R) + sum_a g_ia (d_a(o) - <d_a>),
// with g_ia the coarse gradient of f*_i (central, or one-sided away from the block) and
//   d(o) = x(o) - x(R) - c_i/4   if o + c_i is a block cell (it enters at the first sub-step),
//        = x(o) - x(R) + c_i/4   if o + c_i is not, but o + 2 c_i is (it enters at the second),
//        = x(o) - x(R)           otherwise (it stays in the ring),
// in coarse spacings; <d> is the mean of d over the children. Subtracting the mean makes the
// children average exactly f*_i(R) for every i: the mass a coarse population carries into the
// fine lattice is the mass the coarse lattice loses (the volumetric balance).
// The shifts +-c_i/4 (half a fine spacing) are what make a steady linear shear exact across the
// interface: a post-collision population is the equilibrium taken (tau - 1) dt c_i upstream,
// and (tau_f - 1) dt_f = (tau_c - 1) dt_c + dt_f/2 with tau_f - 1/2 = 2 (tau_c - 1/2).
#include <array>
#include <cstddef>

#include "solver/lbm/refinement/refined_block.hpp"

namespace capsule::lbm::refinement {

// coarse: Q populations per coarse cell (post-collision on uncovered cells); fine: Q per fine cell.
template <class L>
void explode(const RefinedBlock<L::D>& block, const double* coarse, double* fine) {
  constexpr int Q = L::Q, D = L::D;
  const int children = 1 << D;
  const int nzc = D == 3 ? block.fine_n(2) / 2 : 1;
  const int nyc = block.fine_n(1) / 2, nxc = block.fine_n(0) / 2;
  const std::array<int, 3> base = block.parent({0, 0, 0});
  const long cells = long(nxc) * nyc * nzc;
#pragma omp parallel for schedule(static)
  for (long r = 0; r < cells; ++r) {
    std::array<int, 3> R{base[0] + int(r % nxc), base[1] + int((r / nxc) % nyc), base[2] + int(r / (long(nxc) * nyc))};
    for (int a = 0; a < D; ++a)
      if (block.spans(a)) R[a] = (R[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
    if (!block.ring(R)) continue;
    const std::size_t cR = block.coarse_index(R[0], R[1], R[2]);
    // Neighbours used for the gradient: inside the channel and not covered.
    std::array<std::array<std::size_t, 2>, 3> nb{};
    std::array<std::array<bool, 2>, 3> ok{};
    for (int a = 0; a < D; ++a)
      for (int s = 0; s < 2; ++s) {
        std::array<int, 3> N = R;
        N[a] += s == 0 ? -1 : 1;
        if (a != 1) N[a] = (N[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
        ok[a][s] = N[a] >= 0 && N[a] < block.coarse_n(a) && !block.covered(N);
        nb[a][s] = ok[a][s] ? block.coarse_index(N[0], N[1], N[2]) : cR;
      }
    const std::array<int, 3> f0 = block.first_child(R);
    for (int i = 0; i < Q; ++i) {
      const double fR = coarse[cR * Q + i];
      double g[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < D; ++a) {
        const double fm = coarse[nb[a][0] * Q + i], fp = coarse[nb[a][1] * Q + i];
        if (ok[a][0] && ok[a][1]) g[a] = 0.5 * (fp - fm);
        else if (ok[a][1]) g[a] = fp - fR;
        else if (ok[a][0]) g[a] = fR - fm;
      }
      double d[8][3] = {};
      double mean[3] = {0.0, 0.0, 0.0};
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
        for (int a = 0; a < D; ++a) {
          d[k][a] = 0.5 * (((k >> a) & 1) - 0.5) + shift * L::c[i][a];
          mean[a] += d[k][a] / children;
        }
      }
      for (int k = 0; k < children; ++k) {
        std::array<int, 3> o = f0;
        for (int a = 0; a < D; ++a) o[a] += (k >> a) & 1;
        double v = fR;
        for (int a = 0; a < D; ++a) v += g[a] * (d[k][a] - mean[a]);
        fine[block.fine_index(o[0], o[1], o[2]) * Q + i] = v;
      }
    }
  }
}

}  // namespace capsule::lbm::refinement
