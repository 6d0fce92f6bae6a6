#pragma once
// Spreading (21) into a slab of z-layers only, so that threads can spread side by side and
// still give bitwise the serial spread<3>.
//
// The force field is stored z-outermost (grid.index: x fastest, then y, then z), so a run of
// z-layers is one contiguous block. spread_in_layers() visits ALL membrane nodes in mesh order,
// as spread<3> does, but adds only the stencil contributions that land in the layers of its
// arc. Every lattice node of the arc therefore receives exactly the contributions spread<3>
// gives it, in the same order, from the same products: arcs that partition the periodic z axis,
// spread one after the other or on different threads, give bitwise spread<3>, whatever the
// partition. A node whose stencil misses the arc costs one floor().
#include <cstddef>

#include "solver/ib/delta.hpp"
#include "solver/ib/grid.hpp"

namespace capsule::ib {

// The periodic run of z-layers first, first + 1, ..., first + count - 1 (wrapped into [0, nz)).
struct LayerArc {
  int first = 0, count = 0;
  bool holds(int k, int nz) const { return wrap(k - first, nz) < count; }
};

// p[d] += delta(X_c - x) P_c[d] (21) for the lattice nodes x in the layers of `arc` (3D), the
// delta K fixed at compile time. The same walls, periodicity and products as
// for_each_support_node<3> and spread<3>.
template <Delta K>
inline void spread_in_layers_of(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p,
                                LayerArc arc) {
  constexpr int width = delta_width(K);
  double* const p0 = p[0];
  double* const p1 = p[1];
  double* const p2 = p[2];
  for (std::size_t c = 0; c < n; ++c) {
    const double* Xc = X + 3 * c;
    const int z_first = stencil_first(Xc[2], K);
    bool held[width];
    bool any = false;
    for (int l = 0; l < width; ++l) any |= held[l] = arc.holds(wrap(z_first + l, grid.nz), grid.nz);
    if (!any) continue;
    const DeltaStencil1D sx = delta_stencil_of<K>(Xc[0]);
    const DeltaStencil1D sy = delta_stencil_of<K>(Xc[1]);
    const DeltaStencil1D sz = delta_stencil_of<K>(Xc[2]);
    const double Px = P[3 * c], Py = P[3 * c + 1], Pz = P[3 * c + 2];
    int ix[width];
    for (int m = 0; m < width; ++m) ix[m] = wrap(sx.first + m, grid.nx);
    for (int l = 0; l < width; ++l) {
      if (!held[l]) continue;
      const int k = wrap(sz.first + l, grid.nz);
      for (int b = 0; b < width; ++b) {
        const int j = sy.first + b;
        if (j < 0 || j >= grid.ny) continue;  // beyond the walls: dropped, as in spread<3>
        const std::size_t row = grid.index(0, j, k);
        const double wyz = sy.w[b] * sz.w[l];
        for (int m = 0; m < width; ++m) {
          const std::size_t node = row + ix[m];
          const double w = sx.w[m] * wyz;
          p0[node] += w * Px;
          p1[node] += w * Py;
          p2[node] += w * Pz;
        }
      }
    }
  }
}

// The same for a delta named at run time.
inline void spread_in_layers(const Grid& grid, const double* X, const double* P, std::size_t n, double* const* p,
                             Delta delta, LayerArc arc) {
  with_delta(delta, [&](auto k) { spread_in_layers_of<decltype(k)::value>(grid, X, P, n, p, arc); });
}

}  // namespace capsule::ib
