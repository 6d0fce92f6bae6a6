#pragma once
// The Eulerian lattice as the immersed boundary sees it (docs/CONTRACTS.md "Lattice units and geometry"):
// node (i, j, k) sits at (i + 1/2, j + 1/2, k + 1/2), dx = 1; periodic in x (and z),
// walls at y = 0 and y = ny. Linear index i + nx (j + ny k): x runs fastest, as in
// capsule::lbm::Fluid::index.
#include <cmath>
#include <cstddef>

namespace capsule::ib {

struct Grid {
  int nx = 1, ny = 1, nz = 1;  // nz = 1 in 2D

  std::size_t size() const { return static_cast<std::size_t>(nx) * ny * nz; }
  std::size_t index(int i, int j, int k = 0) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * k);
  }
  // Extent along axis d (0 = x, 1 = y, 2 = z).
  int extent(int d) const { return d == 0 ? nx : (d == 1 ? ny : nz); }
  // Axis d is periodic (x and z) or bounded by walls (y).
  static constexpr bool periodic(int d) { return d != 1; }
};

// The first of n markers (D coordinates each in X) that is NaN, beyond a wall (y outside
// [0, ny]) or absurdly far along a periodic axis (|coordinate| > 1e6), -1 when none: a blow-up
// between two outputs, which the next spreading would index the lattice with. The 2D and 3D
// steps stop there and let the member end unstable.
template <int D>
long first_marker_outside(const Grid& g, const double* X, std::size_t n) {
  for (std::size_t c = 0; c < n; ++c)
    for (int d = 0; d < D; ++d) {
      const double x = X[D * c + d];
      if (!std::isfinite(x) || (Grid::periodic(d) ? std::abs(x) > 1e6 : (x < 0.0 || x > g.ny))) return long(c);
    }
  return -1;
}

// Wraps a periodic index into [0, n).
inline int wrap(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

}  // namespace capsule::ib
