#pragma once
// Spreading (21) of a 3D membrane that remembers the box of lattice nodes it wrote, so the
// next step clears only that box.
//
// The force field is zero except where the last spreading wrote: inside the box of the
// stencils of its nodes (x, y, z ranges in lattice nodes). clear_last() zeroes that box, row
// by contiguous row, instead of undoing each node's 4^3-node support one by one
// (clear_support<3>: 2562 nodes x 64 x 3 scattered writes at level 4, each lattice node
// written about twenty times). The spreading itself is spread<3>: serial, in mesh order.
// Measured (docs/findings/performance.md "The membrane side of a 3D step"): a slab-coloured
// parallel spreading, bitwise the same for any thread count, ran no faster on the 2-core
// machine, so it was not kept.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver/ib/interpolation.hpp"

namespace capsule::ib {

class SpreadingBox {
 public:
  // p[d] += sum_c delta(X_c - x) P_c[d] (21): spread<3>(grid, X, P, n, p, kernel), and the box.
  void spread(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p, Kernel kernel) {
    whole_ = !find_box(grid, X, n, kernel);
    ib::spread<3>(grid, X, P, n, p, kernel);
  }

  // Zeroes p[0..2] wherever the last spread() may have written; the whole field before the
  // first spread() and after forget().
  void clear_last(const Grid& grid, double* const* p) const {
    if (whole_) {
      for (int d = 0; d < 3; ++d) std::fill(p[d], p[d] + grid.size(), 0.0);
      return;
    }
    const int y0 = std::max(lo_[1], 0), y1 = std::min(hi_[1], grid.ny);
    const bool whole_rows = hi_[0] - lo_[0] >= grid.nx;
    const int x0 = whole_rows ? 0 : wrap(lo_[0], grid.nx), x_count = whole_rows ? grid.nx : hi_[0] - lo_[0];
    const int before_seam = std::min(x_count, grid.nx - x0);  // the part up to the periodic seam in x
    for (int kz = lo_[2]; kz < hi_[2]; ++kz) {
      const int k = wrap(kz, grid.nz);
      for (int j = y0; j < y1; ++j)
        for (int d = 0; d < 3; ++d) {
          double* row = p[d] + grid.index(0, j, k);
          std::fill(row + x0, row + x0 + before_seam, 0.0);
          std::fill(row, row + (x_count - before_seam), 0.0);  // past the seam, if any
        }
    }
  }

  // The next clear_last() clears the whole field (e.g. after a restart point was loaded).
  void forget() { whole_ = true; }

 private:
  // The box [lo, hi) of all stencils, in unwrapped node indices. False (clear everything)
  // when a position is not finite (or absurdly far) or the box spans the periodic z axis.
  bool find_box(const Grid& grid, const double* X, std::size_t n, Kernel kernel) {
    for (int d = 0; d < 3; ++d) lo_[d] = hi_[d] = 0;
    if (n == 0) return true;
    for (std::size_t i = 0; i < 3 * n; ++i)
      if (!(std::abs(X[i]) < 1e8)) return false;  // NaN, infinite, or too far for an int index
    for (int d = 0; d < 3; ++d) lo_[d] = hi_[d] = stencil_first(X[d], kernel);
    for (std::size_t c = 0; c < n; ++c)
      for (int d = 0; d < 3; ++d) {
        const int f = stencil_first(X[3 * c + d], kernel);
        lo_[d] = std::min(lo_[d], f);
        hi_[d] = std::max(hi_[d], f);
      }
    for (int d = 0; d < 3; ++d) hi_[d] += kernel_width(kernel);  // past the last stencil's last node
    return hi_[2] - lo_[2] <= grid.nz;
  }

  bool whole_ = true;
  int lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
};

}  // namespace capsule::ib
