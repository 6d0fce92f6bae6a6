#pragma once
// Fine-to-coarse transfer ("coalescence", Rohde et al. 2006; docs/guide/refinement.md). After
// the two fine sub-steps, the fine lattice has carried every population bound for a ring cell R
// from a source R - c_i inside the fine lattice (block or ring): the block's outflow of both
// sub-steps and the ring's own exploded populations. The coarse lattice then takes
//   f_i(R) = (1 / 2^D) sum over the children o of R of f_i(o)
// instead of streaming f*_i(R - c_i). Each fine population carries a 2^-D share of a coarse
// cell's volume, so the mass the fine lattice hands back is the mass the coarse one receives.
#include <array>
#include <cstddef>

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

// The children average of population i at ring cell R.
template <class L>
double coalesce(const RefinedBlock<L::D>& block, const double* fine, const std::array<int, 3>& R, int i) {
  constexpr int D = L::D;
  const std::array<int, 3> f0 = block.first_child(R);
  double sum = 0.0;
  for (int k = 0; k < (1 << D); ++k) {
    std::array<int, 3> o = f0;
    for (int a = 0; a < D; ++a) o[a] += (k >> a) & 1;
    sum += fine[block.fine_index(o[0], o[1], o[2]) * L::Q + i];
  }
  return sum / double(1 << D);
}

}  // namespace capsule::lbm::refinement
