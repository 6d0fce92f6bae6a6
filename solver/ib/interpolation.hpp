#pragma once
// Immersed-boundary transfer between Lagrangian membrane nodes and the lattice (Sec. 2.3),
// for Dim = 2 or 3, on plain arrays so the 2D and 3D membranes share it:
//
//   interpolate<Dim>(grid, u, X, n, U, delta)   U(X_c) = sum_j delta(X_c - x_j) u(x_j)   (19)
//   advance<Dim>(X, U, n, dt)                    X_c += U(X_c) dt  (forward Euler)        (20)
//   spread<Dim>(grid, X, P, n, p, delta)        p(x_j) += sum_c delta(X_c - x_j) P(X_c)  (21)
// delta: Delta::cosine (18, the default) or Delta::peskin4 (see delta.hpp for why the 2D
// driver uses peskin4); use the same delta for both directions.
//
// X, U, P: node-major arrays of n * Dim doubles (x0, y0[, z0], x1, ...), positions in
// lattice coordinates (node (i, j, k) at (i + 1/2, j + 1/2, k + 1/2)).
// u, p: Dim pointers to lattice component arrays (SoA) of grid.size() doubles, indexed
// grid.index(i, j, k) (x fastest), e.g. {fluid.velocity(0), fluid.velocity(1)}.
// Each node touches only the 4^Dim lattice nodes of its delta support: O(n 4^Dim) work.
// x (and z) wrap periodically; nodes beyond the walls (j < 0 or j >= ny) are dropped
// (the delta is clipped there; a capsule kept a few nodes away from the walls never sees it).
// spread() adds to p; clear p first (Fluid::clear_force) when starting a step.
#include <cstddef>

#include "solver/ib/delta.hpp"
#include "solver/ib/grid.hpp"

namespace capsule::ib {

// Calls visit(lattice_index, weight) for every lattice node in the support of the
// delta centred at X (Dim coordinates), with walls and periodicity applied; the delta K fixed
// at compile time (its width a constant, the loops unrolled).
template <int Dim, Delta K, class Visit>
inline void for_each_support_node_of(const Grid& grid, const double* X, Visit&& visit) {
  static_assert(Dim == 2 || Dim == 3, "2D or 3D");
  constexpr int width = delta_width(K);
  const DeltaStencil1D sx = delta_stencil_of<K>(X[0]);
  const DeltaStencil1D sy = delta_stencil_of<K>(X[1]);
  int ix[width];
  for (int m = 0; m < width; ++m) ix[m] = wrap(sx.first + m, grid.nx);
  if constexpr (Dim == 2) {
    for (int b = 0; b < width; ++b) {
      const int j = sy.first + b;
      if (j < 0 || j >= grid.ny) continue;
      const std::size_t row = static_cast<std::size_t>(grid.nx) * j;
      for (int m = 0; m < width; ++m) visit(row + ix[m], sx.w[m] * sy.w[b]);
    }
  } else {
    const DeltaStencil1D sz = delta_stencil_of<K>(X[2]);
    for (int c = 0; c < width; ++c) {
      const int k = wrap(sz.first + c, grid.nz);
      for (int b = 0; b < width; ++b) {
        const int j = sy.first + b;
        if (j < 0 || j >= grid.ny) continue;
        const std::size_t row = grid.index(0, j, k);
        const double wyz = sy.w[b] * sz.w[c];
        for (int m = 0; m < width; ++m) visit(row + ix[m], sx.w[m] * wyz);
      }
    }
  }
}

// The same for a delta named at run time (one node; loops over many nodes call with_delta
// once outside the loop instead).
template <int Dim, class Visit>
inline void for_each_support_node(const Grid& grid, const double* X, Delta delta, Visit&& visit) {
  with_delta(delta, [&](auto k) { for_each_support_node_of<Dim, decltype(k)::value>(grid, X, visit); });
}

// (19): velocity of n membrane nodes from the lattice velocity u[0..Dim-1].
template <int Dim>
void interpolate(const Grid& grid, const double* const* u, const double* X, std::size_t n, double* U,
                 Delta delta = Delta::cosine) {
  with_delta(delta, [&](auto k) {
    constexpr Delta K = decltype(k)::value;
    // Each node sums its own support in a fixed order: threads do not change the result. From
    // ~2000 nodes (a 3D mesh at level 4); a 2D membrane's 140 segments stay on one thread.
#pragma omp parallel for schedule(static) if (n > 2048)
    for (std::size_t c = 0; c < n; ++c) {
      double acc[Dim] = {};
      for_each_support_node_of<Dim, K>(grid, X + Dim * c, [&](std::size_t node, double w) {
        for (int d = 0; d < Dim; ++d) acc[d] += w * u[d][node];
      });
      for (int d = 0; d < Dim; ++d) U[Dim * c + d] = acc[d];
    }
  });
}

// (20): forward Euler position update.
template <int Dim>
void advance(double* X, const double* U, std::size_t n, double dt) {
  for (std::size_t i = 0; i < Dim * n; ++i) X[i] += U[i] * dt;
}

// (21): adds the nodal forces P (already integrated over each node's share of the
// membrane) to the lattice body-force density p[0..Dim-1] (dx = 1, so force = density).
template <int Dim>
void spread(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p,
            Delta delta = Delta::cosine) {
  with_delta(delta, [&](auto k) {
    for (std::size_t c = 0; c < n; ++c) {
      const double* Pc = P + Dim * c;
      for_each_support_node_of<Dim, decltype(k)::value>(grid, X + Dim * c, [&](std::size_t node, double w) {
        for (int d = 0; d < Dim; ++d) p[d][node] += w * Pc[d];
      });
    }
  });
}

// Sets p to zero on the support of the nodes X: undoes a spread() from the same positions
// in O(n 4^Dim) instead of clearing the whole lattice.
template <int Dim>
void clear_support(const Grid& grid, const double* X, std::size_t n, double* const* p, Delta delta = Delta::cosine) {
  for (std::size_t c = 0; c < n; ++c)
    for_each_support_node<Dim>(grid, X + Dim * c, delta, [&](std::size_t node, double) {
      for (int d = 0; d < Dim; ++d) p[d][node] = 0.0;
    });
}

}  // namespace capsule::ib
