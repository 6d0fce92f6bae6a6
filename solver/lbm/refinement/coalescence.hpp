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
#include <vector>

#include "solver/lbm/refinement/explosion.hpp"
#include "solver/lbm/refinement/refined_block.hpp"
#include "solver/lbm/refinement/ring_plan.hpp"

namespace capsule::lbm::refinement {

// Population i of ring cell r (RingPlan's position; plan.from_fine set) from the fine lattice,
// with the Taylor coefficients the explosion of this coarse step kept (explosion.hpp); `moved`
// gets the mass (fine cell volumes) the Taylor terms take out of the children's sum.
template <class L, class T>
double coalesce(const RefinedBlock<L::D>& block, const RingPlan<L>& plan, const std::vector<Taylor>& taylor, const T* fine,
                std::size_t r, int i, double& moved) {
  constexpr int D = L::D, children = RingPlan<L>::children;
  const std::size_t ri = r * L::Q + std::size_t(i);
  const Taylor& t = taylor[ri];
  // Taylor coefficients about the source R - c_i: g(R - c_i) = g(R) - h c_i.
  Taylor ts = t;
  for (int a = 0; a < D; ++a) ts.g[a] -= t.h[a] * L::c[i][a];
  const auto& c = plan.cells[r];
  const T* fi = fine + std::size_t(i) * block.fine_size();
  double sum = 0.0, shift_sum = 0.0;
  for (int k = 0; k < children; ++k) {
    sum += fi[c.child[std::size_t(k)]];
    const double shift = 0.25 * plan.coalesce_shift[ri * children + std::size_t(k)];
    // The value stands for the coarse field at R - c_i + e, e = x(o) - x(R) + shift c_i;
    // without the shift it would stand for R - c_i + x(o) - x(R), whose children mean is R - c_i
    // up to the curvature term, which is taken out as well.
    double e[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < D; ++a) e[a] = 0.5 * (((k >> a) & 1) - 0.5) + shift * L::c[i][a];
    shift_sum += ts.change(e);
  }
  moved = shift_sum;
  return (sum - shift_sum) / double(children);
}

}  // namespace capsule::lbm::refinement
