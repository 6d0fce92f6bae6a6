#pragma once
// The lattice rows (y, z) a set of membrane nodes can touch, and the columns x within them:
// the bounding box of the nodes widened by `margin` nodes on each side, as half-open ranges
// [begin, end) in node indices (node j sits at j + 1/2). x and z are periodic: a range may
// start below 0 or end above nx / nz (the user wraps it, e.g. lbm::Fluid::set_macroscopic_region).
// y may reach past the walls (the user clips it).
//
// A node at coordinate x touches nodes floor(x - 1/2) - 1 ... floor(x - 1/2) + 2 with a
// width-4 delta (delta.hpp), i.e. within 2.5 of x; so margin >= 3 covers spreading and
// interpolation at the nodes' own positions, and each further node of margin covers one
// more lattice spacing of stencil (a centred-difference gradient) or of node motion.
// Returns an empty range (begin == end == 0 on both axes) for n = 0, and the whole lattice
// when a coordinate is not finite or the box spans the lattice.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver/ib/grid.hpp"

namespace capsule::ib {

struct RowRange {
  int y_begin = 0, y_end = 0, z_begin = 0, z_end = 0;
  int x_begin = 0, x_end = 0;  // the same along x (periodic): the columns within those rows
};

inline RowRange support_rows(const Grid& grid, const double* X, std::size_t n, int margin) {
  if (n == 0) return {};
  double lo[3] = {X[0], X[1], X[2]}, hi[3] = {X[0], X[1], X[2]};
  for (std::size_t c = 0; c < n; ++c)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], X[3 * c + d]), hi[d] = std::max(hi[d], X[3 * c + d]);
  const RowRange all{0, grid.ny, 0, grid.nz, 0, grid.nx};
  if (!(hi[0] - lo[0] < grid.nx) || !(hi[1] - lo[1] < grid.ny) || !(hi[2] - lo[2] < grid.nz))
    return all;  // NaN, infinite or spanning
  RowRange r;
  r.x_begin = static_cast<int>(std::floor(lo[0])) - margin;
  r.x_end = static_cast<int>(std::floor(hi[0])) + margin + 1;
  r.y_begin = static_cast<int>(std::floor(lo[1])) - margin;
  r.y_end = static_cast<int>(std::floor(hi[1])) + margin + 1;
  r.z_begin = static_cast<int>(std::floor(lo[2])) - margin;
  r.z_end = static_cast<int>(std::floor(hi[2])) + margin + 1;
  return r;
}

}  // namespace capsule::ib
