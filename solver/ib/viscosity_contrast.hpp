#pragma once
// Viscosity contrast V = mu_c / mu_a across the membrane (Sec. 2.2), for Dim = 2 or 3.
//
// For a lattice node x near the membrane: the nearest membrane node X_c, the signed normal
// distance d = (x - X_c) . n_c (n_c its outward unit normal; d > 0 outside), the smoothed
// Heaviside H(d) (15) with h = dx = 1, and mu(x) = mu_c + (mu_a - mu_c) H(d) (16).
// With rho = 1 the kinematic viscosity equals mu, so nu is what the fluid receives.
//
// Only nodes in a band of `band` lattice units around the membrane nodes are recomputed
// (found by visiting the (2 ceil(band) + 1)^Dim box of each membrane node: O(n band^Dim)).
// Elsewhere each node keeps its inside flag: set once by a flood fill from the walls
// through non-band nodes on the first update, and afterwards by the sign of d the last
// time the node was in the band (the membrane moves far less than a node per step).
//
// Usage (once per time step, after moving the membrane):
//   ib::ViscosityContrast<2> vc(grid, nu_outside, nu_inside);
//   vc.update(X, normals, n, [&](std::size_t node, double nu) { fluid.set_viscosity(node, nu); });
// update() calls set(node, nu) for every node whose viscosity may have changed since the
// previous call (every node on the first call). With V = 1 do not use this at all.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "solver/ib/grid.hpp"

namespace capsule::ib {

// (15) with h = 1: 0 for d < -2, 1 for d > 2, smooth in between.
inline double smoothed_heaviside(double d) {
  if (d < -2.0) return 0.0;
  if (d > 2.0) return 1.0;
  return 0.5 * (1.0 + 0.5 * d + std::sin(0.5 * std::numbers::pi * d) / std::numbers::pi);
}

// (16)
inline double contrast_viscosity(double d, double mu_outside, double mu_inside) {
  return mu_inside + (mu_outside - mu_inside) * smoothed_heaviside(d);
}

template <int Dim>
class ViscosityContrast {
  static_assert(Dim == 2 || Dim == 3, "2D or 3D");

 public:
  ViscosityContrast(Grid grid, double nu_outside, double nu_inside, double band = 3.0)
      : grid_(grid), nu_a_(nu_outside), nu_c_(nu_inside), band_(band),
        dist2_(grid.size(), std::numeric_limits<double>::infinity()),
        signed_(grid.size(), 0.0), in_band_(grid.size(), 0), inside_(grid.size(), 0) {}

  template <class Set>
  void update(const double* X, const double* normal, std::size_t n, Set&& set) {
    // Forget the previous band, remembering it to reset nodes that leave it.
    std::swap(previous_band_, band_nodes_);
    band_nodes_.clear();
    for (std::size_t node : previous_band_) {
      in_band_[node] = 0;
      dist2_[node] = std::numeric_limits<double>::infinity();
    }
    const int R = static_cast<int>(std::ceil(band_));
    const double band2 = band_ * band_;
    for (std::size_t c = 0; c < n; ++c) {
      const double* Xc = X + Dim * c;
      const double* nc = normal + Dim * c;
      int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
      for (int d = 0; d < Dim; ++d) {
        lo[d] = static_cast<int>(std::floor(Xc[d] - 0.5)) - R + 1;
        hi[d] = lo[d] + 2 * R - 1;
      }
      const int klo = Dim == 3 ? lo[2] : 0, khi = Dim == 3 ? hi[2] : 0;
      for (int k = klo; k <= khi; ++k) {
        const double dz = Dim == 3 ? (k + 0.5) - Xc[2] : 0.0;
        const int kw = Dim == 3 ? wrap(k, grid_.nz) : 0;
        for (int j = lo[1]; j <= hi[1]; ++j) {
          if (j < 0 || j >= grid_.ny) continue;
          const double dy = (j + 0.5) - Xc[1];
          for (int i = lo[0]; i <= hi[0]; ++i) {
            const double dx = (i + 0.5) - Xc[0];
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 > band2) continue;
            const std::size_t node = grid_.index(wrap(i, grid_.nx), j, kw);
            if (r2 >= dist2_[node]) continue;
            if (!in_band_[node]) {
              in_band_[node] = 1;
              band_nodes_.push_back(node);
            }
            dist2_[node] = r2;
            double sd = dx * nc[0] + dy * nc[1];
            if constexpr (Dim == 3) sd += dz * nc[2];
            signed_[node] = sd;
          }
        }
      }
    }
    for (std::size_t node : band_nodes_) {
      inside_[node] = signed_[node] < 0.0;
      set(node, contrast_viscosity(signed_[node], nu_a_, nu_c_));
    }
    if (!initialised_) {
      flood_fill();
      for (std::size_t node = 0; node < grid_.size(); ++node)
        if (!in_band_[node]) set(node, inside_[node] ? nu_c_ : nu_a_);
      initialised_ = true;
    } else {
      for (std::size_t node : previous_band_)
        if (!in_band_[node]) set(node, inside_[node] ? nu_c_ : nu_a_);
    }
  }

  // Lattice nodes inside the membrane (band nodes by the sign of d, others by their flag).
  bool inside(std::size_t node) const { return inside_[node] != 0; }
  bool in_band(std::size_t node) const { return in_band_[node] != 0; }
  // Signed normal distance of a band node (meaningful only where in_band()).
  double signed_distance(std::size_t node) const { return signed_[node]; }
  const std::vector<std::size_t>& band_nodes() const { return band_nodes_; }

  // Restart points: what the next update() reads besides the membrane -- the inside flag of
  // every node, the current band (reset by the next update) and whether the flood fill ran.
  const std::vector<char>& inside_flags() const { return inside_; }
  bool initialised() const { return initialised_; }
  void restore(const std::vector<char>& inside, const std::vector<std::size_t>& band, bool initialised) {
    if (inside.size() != grid_.size()) throw std::invalid_argument("ViscosityContrast::restore: wrong grid size");
    inside_ = inside;
    std::fill(in_band_.begin(), in_band_.end(), 0);
    std::fill(dist2_.begin(), dist2_.end(), std::numeric_limits<double>::infinity());
    band_nodes_ = band;
    previous_band_.clear();
    for (std::size_t node : band_nodes_) in_band_.at(node) = 1;
    initialised_ = initialised;
  }

 private:
  // Non-band nodes connected to the walls (y = 0 and y = ny rows) are outside; the
  // band encloses the rest, which is inside. Needs a closed band: membrane nodes closer
  // than 2 band (always, with band >= 1 and node spacing below one lattice unit).
  void flood_fill() {
    std::vector<char> outside(grid_.size(), 0);
    std::vector<std::size_t> stack;
    for (int k = 0; k < grid_.nz; ++k)
      for (int i = 0; i < grid_.nx; ++i)
        for (int j : {0, grid_.ny - 1}) {
          const std::size_t node = grid_.index(i, j, k);
          if (!in_band_[node] && !outside[node]) {
            outside[node] = 1;
            stack.push_back(node);
          }
        }
    while (!stack.empty()) {
      const std::size_t node = stack.back();
      stack.pop_back();
      const int i = static_cast<int>(node % grid_.nx);
      const int j = static_cast<int>((node / grid_.nx) % grid_.ny);
      const int k = static_cast<int>(node / (static_cast<std::size_t>(grid_.nx) * grid_.ny));
      auto visit = [&](int ii, int jj, int kk) {
        if (jj < 0 || jj >= grid_.ny) return;
        const std::size_t m = grid_.index(wrap(ii, grid_.nx), jj, wrap(kk, grid_.nz));
        if (in_band_[m] || outside[m]) return;
        outside[m] = 1;
        stack.push_back(m);
      };
      visit(i + 1, j, k);
      visit(i - 1, j, k);
      visit(i, j + 1, k);
      visit(i, j - 1, k);
      if (Dim == 3) {
        visit(i, j, k + 1);
        visit(i, j, k - 1);
      }
    }
    for (std::size_t node = 0; node < grid_.size(); ++node)
      if (!in_band_[node]) inside_[node] = !outside[node];
  }

  Grid grid_;
  double nu_a_, nu_c_, band_;
  std::vector<double> dist2_, signed_;
  std::vector<char> in_band_, inside_;
  std::vector<std::size_t> band_nodes_, previous_band_;
  bool initialised_ = false;
};

}  // namespace capsule::ib
