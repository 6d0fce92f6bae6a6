#pragma once
// The fused stream-collide pass Fluid runs: collide every node with SplitCollision
// (split_collision.hpp) and push the post-collision populations to their neighbours in the
// second lattice (periodic in x and z, half-way bounce-back with the moving-wall correction
// at y = 0 and y = ny), on shifted populations g_i = f_i - w_i stored as T (double or
// float), computed in A.
//
// Macroscopic rows. A row (fixed y, z) flagged in `macroscopic_rows` (or every row when it
// is null) reads the force and writes rho and u; an unflagged row does neither and collides
// with zero force: 56 of the 360 bytes a D3Q19 update moves in double precision. Both give
// bitwise the same populations when the force is zero. The driver
// flags the rows around the membrane (Fluid::set_macroscopic_region).
//
// Templates choose the lattice, precision, viscosity mode, macroscopic row and wall rows
// once, so the x loop has no branches; every (padded) x-row is one `omp simd` loop.
//
// Clones (GNU ifunc, picked by the loader for the CPU): x86-64-v4 (AVX-512, FMA),
// x86-64-v3 (AVX2, FMA), baseline x86-64. The FMA clones contract multiply-adds, so results
// depend on the clone: the same binary on the same CPU with the same thread count gives
// bitwise the same numbers (the kernel has no reductions and a static schedule, so even
// the thread count does not matter: tests/solver/lbm/determinism_test.cpp), but an AVX2-only and
// an AVX-512 machine differ at round-off. CAPSULE_LBM_FAST_CLONES overrides the list.
#include <cstddef>

#include "solver/lbm/padded_rows.hpp"
#include "solver/lbm/parallel.hpp"
#include "solver/lbm/split_collision.hpp"

#if !defined(CAPSULE_LBM_FAST_CLONES) && defined(__x86_64__) && defined(__GNUC__) && defined(__linux__)
#define CAPSULE_LBM_FAST_CLONES "arch=x86-64-v4", "arch=x86-64-v3", "default"
#endif
#ifdef CAPSULE_LBM_FAST_CLONES
#define CAPSULE_LBM_FAST_CLONE_ATTR __attribute__((target_clones(CAPSULE_LBM_FAST_CLONES)))
#else
#define CAPSULE_LBM_FAST_CLONE_ATTR
#endif

namespace capsule::lbm {

template <class T>
struct ShiftedFields {
  int nx, ny, nz;
  std::size_t n;                        // nodes
  PaddedRows rows;                      // layout of the population arrays
  const T* g;                           // Q*rows.per_population(), shifted, level n
  T* g_next;                            // the same, level n+1
  const double* force;                  // 3*n
  double* velocity;                     // 3*n
  double* density;                      // n
  const double* shear_rate;             // n, per-node s_nu (per-node mode only)
  const unsigned char* macroscopic_rows;  // ny*nz flags, or null: every row
  double uniform_shear_rate;            // s_nu (uniform mode)
  double u_bottom, u_top;               // wall x-velocities
};

// flatten: inline the whole collision (lambdas included) so the x loop vectorises.
template <class L, class T, class A, bool per_node, bool trt, bool macro, bool bottom_wall, bool top_wall>
[[gnu::flatten]] CAPSULE_LBM_FAST_CLONE_ATTR void shifted_stream_collide_row(const ShiftedFields<T>& a, int y, int z) {
  constexpr int Q = L::Q;
  using B = MomentBasis<L>;
  const int nx = a.nx;
  const std::size_t n = a.n;
  const std::size_t np = a.rows.per_population();
  const std::size_t row = std::size_t(y) + std::size_t(a.ny) * std::size_t(z);
  const std::size_t base = std::size_t(nx) * row;  // unpadded fields
  const std::size_t pbase = a.rows.index(row, 0);  // this row in a population array

  const T* in[Q];
  T* out[Q];
  static_for<Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    in[i] = a.g + std::size_t(i) * np + pbase;
    constexpr int cy = L::c[i][1];
    constexpr bool leaves = (bottom_wall && cy < 0) || (top_wall && cy > 0);
    if constexpr (leaves) {
      out[i] = a.g_next + std::size_t(B::opposite[i]) * np + pbase;  // bounced back into this node
    } else {
      const int yd = y + cy;
      const int zd = (z + L::c[i][2] + a.nz) % a.nz;
      out[i] = a.g_next + std::size_t(i) * np + a.rows.index(std::size_t(yd) + std::size_t(a.ny) * std::size_t(zd), 0);
    }
  });
  const double* force[3] = {a.force + base, a.force + n + base, a.force + 2 * n + base};
  double* vel[3] = {a.velocity + base, a.velocity + n + base, a.velocity + 2 * n + base};
  double* rho_out = a.density + base;
  const double* s_node = per_node ? a.shear_rate + base : nullptr;
  const A s_uniform = A(a.uniform_shear_rate);
  const A u_bottom = A(a.u_bottom), u_top = A(a.u_top);

  // xm, xp: destination x of populations with c_x = -1, +1 (periodic).
  auto node = [&](int x, int xm, int xp) {
    A g[Q];
    static_for<Q>([&](auto i) __attribute__((always_inline)) { g[i] = A(in[i][x]); });
    A F[3] = {A(0), A(0), A(0)};
    if constexpr (macro) static_for<L::D>([&](auto d) __attribute__((always_inline)) { F[d] = A(force[d][x]); });
    A s_nu;
    if constexpr (per_node) s_nu = A(s_node[x]);
    else s_nu = s_uniform;
    A rho, u[3];
    // Always the forced collision, with F = 0 in the rows that read none: the same
    // operations (and the same FMA contractions) as a macroscopic row with zero force, so a
    // node's populations do not depend on whether its row is flagged (bitwise; the
    // macroscopic-region test checks it).
    SplitCollision<L, A>::template collide<true, trt>(g, F, s_nu, rho, u);
    if constexpr (macro) {
      rho_out[x] = double(rho);
      static_for<L::D>([&](auto d) __attribute__((always_inline)) { vel[d][x] = double(u[d]); });
    }
    static_for<Q>([&](auto ii) __attribute__((always_inline)) {
      constexpr int i = ii;
      constexpr int cx = L::c[i][0];
      constexpr int cy = L::c[i][1];
      // Moving wall: g_opp = g*_i - 6 w_i rho c_i.u_wall (6 w_i = W_i/6; w_opp = w_i, so the
      // shift cancels).
      if constexpr (bottom_wall && cy < 0) {
        out[i][x] = T(g[i] - A(L::weight_numerator[i] * cx / 6.0) * rho * u_bottom);
      } else if constexpr (top_wall && cy > 0) {
        out[i][x] = T(g[i] - A(L::weight_numerator[i] * cx / 6.0) * rho * u_top);
      } else if constexpr (cx > 0) {
        out[i][xp] = T(g[i]);
      } else if constexpr (cx < 0) {
        out[i][xm] = T(g[i]);
      } else {
        out[i][x] = T(g[i]);
      }
    });
  };

  // The whole row in one vector loop: x - 1 = -1 and x + 1 = nx land in the ghost slots.
#pragma omp simd
  for (int x = 0; x < nx; ++x) node(x, x - 1, x + 1);
  // Periodic in x: move the ghosts to their partners. Only this row writes these slots
  // (population i at x = 0 of row r + c_i comes only from x = nx-1 of row r), so no race.
  static_for<Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    constexpr int cx = L::c[i][0];
    constexpr int cy = L::c[i][1];
    constexpr bool leaves = (bottom_wall && cy < 0) || (top_wall && cy > 0);
    if constexpr (!leaves && cx > 0) out[i][0] = out[i][nx];
    if constexpr (!leaves && cx < 0) out[i][nx - 1] = out[i][-1];
  });
}

template <class L, class T, class A, bool per_node, bool trt, bool macro>
inline void shifted_row_walls(const ShiftedFields<T>& a, int y, int z) {
  const bool bottom = (y == 0), top = (y == a.ny - 1);
  if (bottom && top) shifted_stream_collide_row<L, T, A, per_node, trt, macro, true, true>(a, y, z);
  else if (bottom) shifted_stream_collide_row<L, T, A, per_node, trt, macro, true, false>(a, y, z);
  else if (top) shifted_stream_collide_row<L, T, A, per_node, trt, macro, false, true>(a, y, z);
  else shifted_stream_collide_row<L, T, A, per_node, trt, macro, false, false>(a, y, z);
}

template <class L, class T, class A, bool per_node, bool trt = false>
void shifted_stream_collide(const ShiftedFields<T>& a) {
  const long rows = long(a.ny) * long(a.nz);
  const int ny = a.ny;
  const bool parallel = a.n >= parallel_threshold_nodes;
#pragma omp parallel for schedule(static) if (parallel)
  for (long r = 0; r < rows; ++r) {
    const int y = int(r % ny), z = int(r / ny);
    if (!a.macroscopic_rows || a.macroscopic_rows[r]) shifted_row_walls<L, T, A, per_node, trt, true>(a, y, z);
    else shifted_row_walls<L, T, A, per_node, trt, false>(a, y, z);
  }
}

}  // namespace capsule::lbm
