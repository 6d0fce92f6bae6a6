#pragma once
// Fine-to-coarse transfer ("coalescence", Rohde et al. 2006; docs/guide/refinement.md). After
// the two fine sub-steps, the fine lattice has carried every population bound for a ring cell R
// from a source R - c_i inside the fine lattice (block or ring): the block's outflow of both
// sub-steps and the ring's own exploded populations. The coarse lattice then takes the children
// average instead of streaming f*_i(R - c_i):
//   f_i(R) = (1 / 2^D) sum_o [ f_i(o) - T_i(d(o) + s(o, i)) ],
// with T_i(e) = f*_i(R - c_i + e) - f*_i(R - c_i) from the coarse Taylor coefficients
// (explosion.hpp), d(o) = x(o) - x(R), and s the shift of the population's origin:
//   s = +c_i/4 if it left the block at the second sub-step (o - c_i a block cell),
//       -c_i/4 if at the first (o - 2 c_i a block cell), 0 if it never entered the block,
// in coarse spacings. A block cell's post-collision population is the coarse one half a fine
// spacing upstream (explosion.hpp), so in a flow linear in space the average is exactly the
// coarse f*_i(R - c_i) (and, with the curvature terms, in a quadratic one such as f* of a linear
// shear). The terms do not average to zero at the block's edges and corners; the mass they move
// is returned to the fluid's balance (refined_fluid.hpp).
#include <array>
#include <cstddef>

#include "solver/lbm/refinement/explosion.hpp"
#include "solver/lbm/refinement/refined_block.hpp"

namespace capsule::lbm::refinement {

// Does ring cell R take direction i from the fine lattice? (R must be uncovered.)
template <class L>
bool from_fine(const RefinedBlock<L::D>& block, const std::array<int, 3>& R, int i) {
  if (!block.ring(R)) return false;
  std::array<int, 3> S = R;
  for (int a = 0; a < L::D; ++a) {
    S[a] -= L::c[i][a];
    if (a != 1) S[a] = (S[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
  }
  if (S[1] < 0 || S[1] >= block.coarse_n(1)) return false;
  return block.in_fine_lattice(S);
}

// Population i of ring cell R from the fine lattice; `moved` gets the mass (fine cell volumes)
// the Taylor terms take out of the children's sum.
template <class L>
double coalesce(const RefinedBlock<L::D>& block, const double* coarse_post, const double* fine,
                const std::array<int, 3>& R, int i, double& moved) {
  constexpr int D = L::D;
  const Taylor t = coarse_taylor<L>(block, coarse_post, R, i);
  // Taylor coefficients about the source R - c_i: g(R - c_i) = g(R) - h c_i.
  Taylor ts = t;
  for (int a = 0; a < D; ++a) ts.g[a] -= t.h[a] * L::c[i][a];
  const std::array<int, 3> f0 = block.first_child(R);
  double sum = 0.0, shift_sum = 0.0;
  for (int k = 0; k < (1 << D); ++k) {
    std::array<int, 3> o = f0;
    for (int a = 0; a < D; ++a) o[a] += (k >> a) & 1;
    sum += fine[block.fine_index(o[0], o[1], o[2]) * L::Q + i];
    std::array<int, 3> o1 = o, o2 = o;
    for (int a = 0; a < D; ++a) {
      o1[a] -= L::c[i][a];
      o2[a] -= 2 * L::c[i][a];
    }
    double shift = 0.0;
    if (block.wrap_fine(o1) && block.fine_in_block(o1)) shift = 0.25;
    else if (block.wrap_fine(o2) && block.fine_in_block(o2)) shift = -0.25;
    // The value stands for the coarse field at R - c_i + e, e = x(o) - x(R) + shift c_i;
    // without the shift it would stand for R - c_i + x(o) - x(R), whose children mean is R - c_i
    // up to the curvature term, which is taken out as well.
    double e[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < D; ++a) e[a] = 0.5 * (((k >> a) & 1) - 0.5) + shift * L::c[i][a];
    shift_sum += ts.change(e);
  }
  moved = shift_sum;
  return (sum - shift_sum) / double(1 << D);
}

}  // namespace capsule::lbm::refinement
