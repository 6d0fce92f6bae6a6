#pragma once
// Fine-to-coarse transfer ("coalescence", Rohde et al. 2006; docs/guide/refinement.md). After
// the two fine sub-steps, the fine lattice has carried every population bound for a ring cell R
// from a source R - c_i inside the fine lattice (block or ring): the block's outflow of both
// sub-steps and the ring's own exploded populations. The coarse lattice then takes the children
// average instead of streaming f*_i(R - c_i):
//   f_i(R) = (1 / 2^D) sum_o [ f_i(o) - g_i . s(o, i) ],
// with g_i the coarse gradient at R (explosion.hpp) and s the shift of the population's origin:
//   s = +c_i/4 if it left the block at the second sub-step (o - c_i a block cell),
//       -c_i/4 if at the first (o - 2 c_i a block cell), 0 if it never entered the block,
// in coarse spacings. A block cell's post-collision population is the coarse one half a fine
// spacing upstream (explosion.hpp), so in a flow linear in space the average is exactly the
// coarse f*_i(R - c_i). The shifts average to zero along a plane face; at edges and corners the
// mass they move, 2^D g_i . <s>, is returned to the fluid's balance (refined_fluid.hpp).
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

// Population i of ring cell R from the fine lattice; `moved` gets the shift's mass, 2^D g_i . <s>
// (fine cell volumes), that the value leaves out.
template <class L>
double coalesce(const RefinedBlock<L::D>& block, const double* coarse_post, const double* fine,
                const std::array<int, 3>& R, int i, double& moved) {
  constexpr int D = L::D;
  double g[3];
  coarse_gradient<L>(block, coarse_post, R, i, g);
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
    for (int a = 0; a < D; ++a) shift_sum += g[a] * shift * L::c[i][a];
  }
  moved = shift_sum;
  return (sum - shift_sum) / double(1 << D);
}

}  // namespace capsule::lbm::refinement
