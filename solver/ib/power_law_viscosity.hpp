#pragma once
// Power-law membrane viscosity as added fluid viscosity (Sec. 5.2, (99)-(104)), for Dim = 2 or 3.
//
// Per update, from the lattice velocity u and the membrane nodes X_c (outward unit normals n_c,
// areas a_c: Voronoi areas (83) in 3D):
//   (99)  grad U(X_c) = sum_j delta(X_c - x_j) grad u(x_j), grad u by second-order centred
//         differences (periodic in x and z; one-sided at the wall rows, which a capsule a few
//         nodes from the walls never reaches);
//   (100) D = P (grad U + grad U^T)/2 P, P = I - n n;
//   (101) gamma = sqrt(2 tr D^2);
//   (102) mu_mem = K a mu_a (gamma / k)^(n - 1), a surface viscosity (viscosity x length) like
//         the Kelvin-Voigt mu_s = eta a mu_a (36): K is dimensionless, on the scale of eta, and
//         gamma is measured in units of the shear rate k (docs/conventions.md "Power-law K"; the text quotes K in
//         multiples of mu_a without the units of gamma, and reports that its K and mu_s =
//         1000 K behave alike, so its K = 0.01 is K = 10 here). gamma / k is floored at
//         `gamma_floor` (default 0.01): a rigid-body part of the motion, or the points of the
//         tangent plane where the shear has no in-plane part, give gamma = 0, where mu_mem
//         diverges for n < 1;
//   (103) mu_mem(x_j) = sum_c delta(X_c - x_j) mu_mem(X_c) a_c, the surface viscosity spread as
//         a shell whose viscosity integrates across the membrane to mu_mem. (103) prints a
//         further 1/h, which does not balance the units; h = 1 here, so the numbers agree.
// The caller adds field(node) to the fluid's own viscosity there, (104) (rho = 1, so the
// kinematic viscosity is mu). The field is zero except on the support of the last update;
// touched() and previously_touched() list the nodes whose value may have changed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "solver/ib/interpolation.hpp"

namespace capsule::ib {

struct PowerLawParameters {
  double K = 0;            // flow consistency index, dimensionless (102): mu_s / (a mu_a) at gamma = k
  double n = 1;            // flow behaviour index (102)
  double mu_a = 0;         // ambient dynamic viscosity (lattice units)
  double a = 1;            // capsule radius (lattice units)
  double shear_rate = 0;   // k (lattice units): gamma is measured in units of k
  double gamma_floor = 0.01;  // smallest gamma / k used in (102)
};

template <int Dim>
class PowerLawViscosity {
  static_assert(Dim == 2 || Dim == 3, "2D or 3D");

 public:
  using Tensor = std::array<std::array<double, Dim>, Dim>;  // g[d][e] = d u_d / d x_e

  PowerLawViscosity(Grid grid, Delta delta, PowerLawParameters p)
      : grid_(grid), delta_(delta), p_(p), field_(grid.size(), 0.0), slot_(grid.size(), -1) {}

  // (99)-(103). X, normal: n * Dim doubles; area: n doubles; u: Dim lattice velocity arrays.
  void update(const double* X, const double* normal, const double* area, std::size_t n, const double* const* u) {
    // The new support, each lattice node once (the supports of neighbouring vertices overlap
    // about 30-fold), after clearing the previous one's field.
    std::swap(previous_, touched_);
    for (std::size_t node : previous_) field_[node] = 0.0, slot_[node] = -1;
    touched_.clear();
    for (std::size_t c = 0; c < n; ++c)
      for_each_support_node<Dim>(grid_, X + Dim * c, delta_, [&](std::size_t node, double) {
        if (slot_[node] < 0) slot_[node] = static_cast<long>(touched_.size()), touched_.push_back(node);
      });
    // Centred-difference gradients, once per support node.
    grad_.resize(touched_.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < static_cast<long>(touched_.size()); ++i) grad_[i] = lattice_gradient(touched_[i], u);
    gamma_.resize(n);
    mu_.resize(n);
#pragma omp parallel for schedule(static)
    for (long c = 0; c < static_cast<long>(n); ++c) {
      Tensor g{};
      for_each_support_node<Dim>(grid_, X + Dim * c, delta_, [&](std::size_t node, double w) {
        const Tensor& gn = grad_[slot_[node]];
        for (int d = 0; d < Dim; ++d)
          for (int e = 0; e < Dim; ++e) g[d][e] += w * gn[d][e];  // (99)
      });
      gamma_[c] = surface_shear_rate(g, normal + Dim * c);
      mu_[c] = viscosity(gamma_[c]);
    }
    // (103), serial: the supports overlap.
    for (std::size_t c = 0; c < n; ++c) {
      const double m = mu_[c] * area[c];
      for_each_support_node<Dim>(grid_, X + Dim * c, delta_, [&](std::size_t node, double w) { field_[node] += w * m; });
    }
  }

  // (100)-(101) for a velocity gradient g[d][e] = d u_d / d x_e and an outward unit normal.
  static double surface_shear_rate(const Tensor& g, const double* normal) {
    Tensor P{}, S{}, D{};
    for (int d = 0; d < Dim; ++d)
      for (int e = 0; e < Dim; ++e) {
        P[d][e] = (d == e ? 1.0 : 0.0) - normal[d] * normal[e];
        S[d][e] = 0.5 * (g[d][e] + g[e][d]);
      }
    double trD2 = 0;
    for (int d = 0; d < Dim; ++d)
      for (int e = 0; e < Dim; ++e) {
        double v = 0;
        for (int l = 0; l < Dim; ++l)
          for (int m = 0; m < Dim; ++m) v += P[d][l] * S[l][m] * P[m][e];
        D[d][e] = v;
      }
    for (int d = 0; d < Dim; ++d)
      for (int e = 0; e < Dim; ++e) trD2 += D[d][e] * D[e][d];
    return std::sqrt(2.0 * std::max(trD2, 0.0));
  }

  // (102): the surface viscosity at a shear rate gamma (lattice units).
  double viscosity(double gamma) const {
    const double g = std::max(gamma / p_.shear_rate, p_.gamma_floor);
    return p_.K * p_.a * p_.mu_a * std::pow(g, p_.n - 1.0);
  }

  // Centred-difference velocity gradient at a lattice node.
  Tensor lattice_gradient(std::size_t node, const double* const* u) const {
    const std::size_t nx = grid_.nx, nxy = nx * grid_.ny;
    const int i = static_cast<int>(node % nx);
    const int j = static_cast<int>((node / nx) % grid_.ny);
    const int k = static_cast<int>(node / nxy);
    Tensor g{};
    // x: periodic
    const std::size_t xm = node - i + wrap(i - 1, grid_.nx), xp = node - i + wrap(i + 1, grid_.nx);
    for (int d = 0; d < Dim; ++d) g[d][0] = 0.5 * (u[d][xp] - u[d][xm]);
    // y: walls; one-sided next to them
    {
      const bool lo = j == 0, hi = j == grid_.ny - 1;
      const std::size_t ym = lo ? node : node - nx, yp = hi ? node : node + nx;
      const double inv = (lo || hi) ? 1.0 : 0.5;
      for (int d = 0; d < Dim; ++d) g[d][1] = inv * (u[d][yp] - u[d][ym]);
    }
    if constexpr (Dim == 3) {
      const std::size_t base = node - static_cast<std::size_t>(k) * nxy;
      const std::size_t zm = base + static_cast<std::size_t>(wrap(k - 1, grid_.nz)) * nxy;
      const std::size_t zp = base + static_cast<std::size_t>(wrap(k + 1, grid_.nz)) * nxy;
      for (int d = 0; d < Dim; ++d) g[d][2] = 0.5 * (u[d][zp] - u[d][zm]);
    }
    return g;
  }

  // Per membrane node, from the last update: gamma (lattice units) and mu_mem (102).
  const std::vector<double>& gamma() const { return gamma_; }
  const std::vector<double>& membrane_viscosity() const { return mu_; }
  // (103) at a lattice node; zero off the last support.
  double field(std::size_t node) const { return field_[node]; }
  const std::vector<std::size_t>& touched() const { return touched_; }
  const std::vector<std::size_t>& previously_touched() const { return previous_; }
  const PowerLawParameters& parameters() const { return p_; }

 private:
  Grid grid_;
  Delta delta_;
  PowerLawParameters p_;
  std::vector<double> gamma_, mu_;
  std::vector<double> field_;
  std::vector<long> slot_;    // index into touched_ and grad_, -1 off the current support
  std::vector<Tensor> grad_;  // centred-difference gradient at touched_[i]
  std::vector<std::size_t> touched_, previous_;
};

}  // namespace capsule::ib
