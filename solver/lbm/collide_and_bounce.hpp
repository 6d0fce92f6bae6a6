#pragma once
// The node update every fused stream-collide pass shares: load a node's populations, collide
// them (with the force, where the row reads it), write rho and u where the row is macroscopic,
// and store each post-collision population at its destination, a population leaving through a
// moving wall bounced back half-way into the opposite slot of the same node:
//   g_opp = g*_i - 6 w_i rho c_i.u_wall   (6 w_i = W_i/6; w_opp = w_i, so a shift cancels).
// The passes differ only in where a population is read and goes (RowAccess, set per row):
// shifted_stream_collide.hpp between two lattices, in_place_stream_collide.hpp in one array,
// and the benchmark's baseline (solver/bench/baseline_stream_collide.hpp).
#include <cstddef>

#include "solver/lbm/moment_basis.hpp"
#include "solver/lbm/static_for.hpp"

// The row functions are cloned (GNU ifunc, picked by the loader for the CPU): x86-64-v4
// (AVX-512, FMA), x86-64-v3 (AVX2, FMA), baseline x86-64. The FMA clones contract
// multiply-adds, so an AVX2-only and an AVX-512 machine differ at round-off (the same binary
// on the same CPU gives bitwise the same numbers at any thread count:
// tests/solver/lbm/determinism_test.cpp). CAPSULE_LBM_FAST_CLONES overrides the list.
#if !defined(CAPSULE_LBM_FAST_CLONES) && defined(__x86_64__) && defined(__GNUC__) && defined(__linux__)
#define CAPSULE_LBM_FAST_CLONES "arch=x86-64-v4", "arch=x86-64-v3", "default"
#endif
#ifdef CAPSULE_LBM_FAST_CLONES
#define CAPSULE_LBM_FAST_CLONE_ATTR __attribute__((target_clones(CAPSULE_LBM_FAST_CLONES)))
#else
#define CAPSULE_LBM_FAST_CLONE_ATTR
#endif

namespace capsule::lbm {

// Where the nodes of one row read and write: in[i] + x holds population i of node x; a
// population i of node x goes to out[i] + x, + xp (c_x = +1) or + xm (c_x = -1), or, leaving
// through a wall, to out[i] + x (out[i] then points at the opposite population's slot).
template <class L, class T, class A>
struct RowAccess {
  const T* in[L::Q];
  T* out[L::Q];
  const double* force[3];
  double* velocity[3];
  double* density;
  const double* shear_rate;  // per-node s_nu, or null (uniform)
  A uniform_shear_rate;
  A u_bottom, u_top;         // wall x-velocities
};

// One node x. Collide::collide(g, F, s_nu, rho, u) is the collision; the forced one always,
// with F = 0 in the rows that read none: the same operations (and the same FMA contractions)
// as a macroscopic row with zero force, so a node's populations do not depend on whether its
// row is flagged (bitwise; tests/solver/lbm/macroscopic_region_test.cpp).
template <class L, class T, class A, class Collide, bool per_node, bool macro, bool bottom_wall, bool top_wall>
[[gnu::always_inline]] inline void collide_and_bounce(const RowAccess<L, T, A>& r, int x, int xm, int xp) {
  constexpr int Q = L::Q;
  A g[Q];
  static_for<Q>([&](auto i) __attribute__((always_inline)) { g[i] = A(r.in[i][x]); });
  A F[3] = {A(0), A(0), A(0)};
  if constexpr (macro) static_for<L::D>([&](auto d) __attribute__((always_inline)) { F[d] = A(r.force[d][x]); });
  A s_nu;
  if constexpr (per_node) s_nu = A(r.shear_rate[x]);
  else s_nu = r.uniform_shear_rate;
  A rho, u[3];
  Collide::collide(g, F, s_nu, rho, u);
  if constexpr (macro) {
    r.density[x] = double(rho);
    static_for<L::D>([&](auto d) __attribute__((always_inline)) { r.velocity[d][x] = double(u[d]); });
  }
  static_for<Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    constexpr int cx = L::c[i][0];
    constexpr int cy = L::c[i][1];
    if constexpr (bottom_wall && cy < 0) {
      r.out[i][x] = T(g[i] - A(L::weight_numerator[i] * cx / 6.0) * rho * r.u_bottom);
    } else if constexpr (top_wall && cy > 0) {
      r.out[i][x] = T(g[i] - A(L::weight_numerator[i] * cx / 6.0) * rho * r.u_top);
    } else if constexpr (cx > 0) {
      r.out[i][xp] = T(g[i]);
    } else if constexpr (cx < 0) {
      r.out[i][xm] = T(g[i]);
    } else {
      r.out[i][x] = T(g[i]);
    }
  });
}

// Two lattices, periodic in x: population i of a row goes to the row y + c_y, z + c_z of the
// next lattice (z periodic), or back into this node's opposite slot at a wall.
template <class L, class T, class A, class Rows, bool bottom_wall, bool top_wall>
[[gnu::always_inline]] inline void point_two_lattice_row(RowAccess<L, T, A>& r, const T* g, T* g_next, const Rows& rows,
                                                          std::size_t np, int y, int z, int ny, int nz) {
  const std::size_t pbase = rows.index(std::size_t(y) + std::size_t(ny) * std::size_t(z), 0);
  static_for<L::Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    r.in[i] = g + std::size_t(i) * np + pbase;
    constexpr int cy = L::c[i][1];
    constexpr bool leaves = (bottom_wall && cy < 0) || (top_wall && cy > 0);
    if constexpr (leaves) {
      r.out[i] = g_next + std::size_t(MomentBasis<L>::opposite[i]) * np + pbase;  // bounced back into this node
    } else {
      const int yd = y + cy;
      const int zd = (z + L::c[i][2] + nz) % nz;
      r.out[i] = g_next + std::size_t(i) * np + rows.index(std::size_t(yd) + std::size_t(ny) * std::size_t(zd), 0);
    }
  });
}

// Two lattices, periodic in x: after a row's vector loop (x - 1 = -1 and x + 1 = nx land in the
// ghost slots) the ghosts move to their partners. Only this row writes these slots (population
// i at x = 0 of row r + c_i comes only from x = nx-1 of row r), so no race.
template <class L, class T, class A, bool bottom_wall, bool top_wall>
[[gnu::always_inline]] inline void wrap_x_ghosts(const RowAccess<L, T, A>& r, int nx) {
  static_for<L::Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    constexpr int cx = L::c[i][0];
    constexpr int cy = L::c[i][1];
    constexpr bool leaves = (bottom_wall && cy < 0) || (top_wall && cy > 0);
    if constexpr (!leaves && cx > 0) r.out[i][0] = r.out[i][nx];
    if constexpr (!leaves && cx < 0) r.out[i][nx - 1] = r.out[i][-1];
  });
}

// The row (y, z)'s fields from a pass's fields (force, velocity and density unpadded, n nodes;
// the per-node s_nu where per_node; the uniform s_nu and the wall velocities).
template <bool per_node, class L, class T, class A, class Fields>
[[gnu::always_inline]] inline void point_row_fields(RowAccess<L, T, A>& r, const Fields& a, int y, int z) {
  const std::size_t base = std::size_t(a.nx) * (std::size_t(y) + std::size_t(a.ny) * std::size_t(z));
  for (int d = 0; d < 3; ++d) {
    r.force[d] = a.force + std::size_t(d) * a.n + base;
    r.velocity[d] = a.velocity + std::size_t(d) * a.n + base;
  }
  r.density = a.density + base;
  r.shear_rate = per_node ? a.shear_rate + base : nullptr;
  r.uniform_shear_rate = A(a.uniform_shear_rate);
  r.u_bottom = A(a.u_bottom);
  r.u_top = A(a.u_top);
}

}  // namespace capsule::lbm
