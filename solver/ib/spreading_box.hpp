#pragma once
// Spreading (21) of a 3D membrane that remembers the box of lattice nodes it wrote, so the
// next step clears only that box.
//
// The force field is zero except where the last spreading wrote: inside the bounding box of
// its nodes widened by the stencils' reach (ib::support_rows: x, y and z ranges in nodes).
// clear_last() zeroes that box, row by contiguous row, instead of undoing each node's
// 4^3-node support one by one
// (clear_support<3>: 2562 nodes x 64 x 3 scattered writes at level 4, each lattice node
// written about twenty times). The spreading itself is spread<3>: serial, in mesh order.
// Measured (docs/findings/performance.md "The membrane side of a 3D step"): a slab-coloured
// parallel spreading, bitwise the same for any thread count, ran no faster on the 2-core
// machine, so it was not kept.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver/ib/interpolation.hpp"
#include "solver/ib/support_rows.hpp"

namespace capsule::ib {

class SpreadingBox {
 public:
  // p[d] += sum_c delta(X_c - x) P_c[d] (21): spread<3>(grid, X, P, n, p, kernel), and the box.
  void spread(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p, Kernel kernel) {
    whole_ = !find_box(grid, X, n);
    ib::spread<3>(grid, X, P, n, p, kernel);
  }

  // Zeroes p[0..2] wherever the last spread() may have written; the whole field before the
  // first spread() and after forget().
  void clear_last(const Grid& grid, double* const* p) const {
    if (whole_) {
      for (int d = 0; d < 3; ++d) std::fill(p[d], p[d] + grid.size(), 0.0);
      return;
    }
    const int y0 = std::max(box_.y_begin, 0), y1 = std::min(box_.y_end, grid.ny);
    const bool whole_rows = box_.x_end - box_.x_begin >= grid.nx;
    const int x0 = whole_rows ? 0 : wrap(box_.x_begin, grid.nx), x_count = whole_rows ? grid.nx : box_.x_end - box_.x_begin;
    const int before_seam = std::min(x_count, grid.nx - x0);  // the part up to the periodic seam in x
    for (int kz = box_.z_begin; kz < box_.z_end; ++kz) {
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
  // Every delta kernel's stencil lies within 3 nodes of its point (support_rows.hpp): the box
  // of the nodes widened by 3 holds every node spread<3> writes. Stencils that would wrap onto
  // themselves in z (a membrane as tall as the box) leave no box: clear everything.
  static constexpr int kStencilReach = 3;
  bool find_box(const Grid& grid, const double* X, std::size_t n) {
    box_ = support_rows(grid, X, n, kStencilReach);
    return box_.z_end - box_.z_begin <= grid.nz;
  }

  bool whole_ = true;
  RowRange box_;
};

}  // namespace capsule::ib
