#pragma once
// Spreading (21) of a 3D membrane that remembers the box of lattice nodes it wrote, so the
// next step clears only that box; both on all threads, bitwise the serial spread<3>.
//
// The force field is zero except where the last spreading wrote: inside the bounding box of
// its nodes widened by the stencils' reach (ib::support_rows: x, y and z ranges in nodes).
// Clearing zeroes that box, row by contiguous row, instead of undoing each node's 4^3-node
// support one by one (clear_support<3>: 2562 nodes x 64 x 3 scattered writes at level 4, each
// lattice node written about twenty times).
//
// Threads: the periodic z axis (the outermost index of the force field) is cut into one arc of
// layers per thread, the box's layers shared evenly, the layers outside it going to the last
// thread. Each thread clears the last box within its own arc and then spreads into it
// (spread_in_layers: every node in mesh order, only the contributions that land in the arc), so
// every lattice node is cleared and receives its contributions in the serial order, from one
// thread: the field is bitwise that of spread<3> for any thread count, and no thread waits for
// another between clearing and spreading.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver/ib/interpolation.hpp"
#include "solver/ib/layer_spreading.hpp"
#include "solver/ib/support_rows.hpp"

namespace capsule::ib {

class SpreadingBox {
 public:
  // Zeroes p[0..2] wherever the last spread may have written, then p[d] += sum_c delta(X_c - x)
  // P_c[d] (21) (= spread<3>(grid, X, P, n, p, delta)), and remembers the new box.
  void clear_last_and_spread(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p,
                             Delta delta) {
    const RowRange last = box_;
    const bool last_whole = whole_;
    whole_ = !find_box(grid, X, n);
#pragma omp parallel if (n > kThreadedFrom)
    {
      const LayerArc arc = thread_arc(grid, omp_get_thread_num(), omp_get_num_threads());
      clear(grid, p, last, last_whole, arc);
      spread_in_layers(grid, X, P, n, p, delta, arc);
    }
  }

  // The two halves alone: spread (21) without clearing, and clearing without spreading.
  void spread(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p, Delta delta) {
    whole_ = !find_box(grid, X, n);
#pragma omp parallel if (n > kThreadedFrom)
    spread_in_layers(grid, X, P, n, p, delta, thread_arc(grid, omp_get_thread_num(), omp_get_num_threads()));
  }
  // Zeroes p[0..2] wherever the last spread may have written; the whole field before the
  // first spread and after forget().
  void clear_last(const Grid& grid, double* const* p) const { clear(grid, p, box_, whole_, LayerArc{0, grid.nz}); }

  // The next clearing clears the whole field (e.g. after a restart point was loaded).
  void forget() { whole_ = true; }

 private:
  // Threads from about a level-4 membrane (2562 nodes), as interpolate<3>; fewer nodes spread
  // in less time than a fork costs on shared cores.
  static constexpr std::size_t kThreadedFrom = 2048;
  // Every delta's stencil lies within 3 nodes of its point (support_rows.hpp): the box
  // of the nodes widened by 3 holds every node spread<3> writes. Stencils that would wrap onto
  // themselves in z (a membrane as tall as the box) leave no box: clear everything.
  static constexpr int kStencilReach = 3;
  bool find_box(const Grid& grid, const double* X, std::size_t n) {
    box_ = support_rows(grid, X, n, kStencilReach);
    return box_.z_end - box_.z_begin <= grid.nz;
  }

  // Thread t of `threads`: its share of the current box's layers; the last thread also takes
  // the layers outside the box, so that the arcs cover the periodic z axis once.
  LayerArc thread_arc(const Grid& grid, int t, int threads) const {
    const int z0 = whole_ ? 0 : box_.z_begin, layers = whole_ ? grid.nz : box_.z_end - box_.z_begin;
    const int first = z0 + layers * t / threads;
    const int end = t + 1 == threads ? z0 + grid.nz : z0 + layers * (t + 1) / threads;
    return {first, end - first};
  }

  // Zeroes the part of the box (all of the field when whole) within the layers of arc.
  static void clear(const Grid& grid, double* const* p, const RowRange& box, bool whole, LayerArc arc) {
    const std::size_t layer = static_cast<std::size_t>(grid.nx) * grid.ny;
    if (whole) {
      for (int l = 0; l < arc.count; ++l) {
        const std::size_t k = wrap(arc.first + l, grid.nz);
        for (int d = 0; d < 3; ++d) std::fill(p[d] + k * layer, p[d] + (k + 1) * layer, 0.0);
      }
      return;
    }
    const int y0 = std::max(box.y_begin, 0), y1 = std::min(box.y_end, grid.ny);
    const bool whole_rows = box.x_end - box.x_begin >= grid.nx;
    const int x0 = whole_rows ? 0 : wrap(box.x_begin, grid.nx), x_count = whole_rows ? grid.nx : box.x_end - box.x_begin;
    const int before_seam = std::min(x_count, grid.nx - x0);  // the part up to the periodic seam in x
    for (int kz = box.z_begin; kz < box.z_end; ++kz) {
      const int k = wrap(kz, grid.nz);
      if (!arc.holds(k, grid.nz)) continue;
      for (int j = y0; j < y1; ++j)
        for (int d = 0; d < 3; ++d) {
          double* row = p[d] + grid.index(0, j, k);
          std::fill(row + x0, row + x0 + before_seam, 0.0);
          std::fill(row, row + (x_count - before_seam), 0.0);  // past the seam, if any
        }
    }
  }

  bool whole_ = true;
  RowRange box_;
};

}  // namespace capsule::ib
