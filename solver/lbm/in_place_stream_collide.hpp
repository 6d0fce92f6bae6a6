#pragma once
// In-place streaming (the AA pattern of Bailey et al. 2009): one population array instead
// of two, so a step moves each population once in and once out and no write-allocate
// traffic for a second lattice. Same collision (SplitCollision), same walls, same
// precision choices and macroscopic rows as the two-lattice kernel
// (shifted_stream_collide.hpp), which it equals bitwise (tests/solver/lbm/in_place_test.cpp).
//
// Two alternating steps on the array A[i][x] (SoA, padded rows, shifted populations):
//  - natural state (after initialisation and after every odd step): f_i(x) sits in A[i][x].
//    Even step: node x reads A[i][x], collides, writes f*_i to A[opp(i)][x] -- node-local.
//  - swapped state (after an even step): f_j(x) sits in A[opp(j)][x - c_j], or in A[j][x]
//    where x - c_j is beyond a wall (the bounced population). Odd step: node x reads there,
//    collides, and writes f*_j to A[j][x + c_j], or to A[opp(j)][x] where x + c_j is beyond a
//    wall. Every slot is read and written by exactly one node, so the pass is race-free
//    in place.
// Moving walls: f*_i leaving through a wall comes back as f*_i - 6 w_i rho c_i.u_wall into
// the opposite slot of the same node, with rho and u_wall of the step that emits it (the
// two-lattice kernel does the same, so both give the same numbers).
// Periodic x: the odd step reaches x = -1 and x = nx; before it those ghost slots get
// copies of x = nx-1 and 0 (only the slots a node really reaches), afterwards the copies
// go back. z wraps by row arithmetic.
#include <cstddef>

#include "solver/lbm/padded_rows.hpp"
#include "solver/lbm/parallel.hpp"
#include "solver/lbm/shifted_stream_collide.hpp"
#include "solver/lbm/split_collision.hpp"

namespace capsule::lbm {

template <class T>
struct InPlaceFields {
  int nx, ny, nz;
  std::size_t n;                          // nodes
  PaddedRows rows;                        // layout of the population array
  T* g;                                   // Q*rows.per_population(), shifted
  const double* force;                    // 3*n
  double* velocity;                       // 3*n
  double* density;                        // n
  const double* shear_rate;               // n, per-node s_nu (per-node mode only)
  const unsigned char* macroscopic_rows;  // ny*nz flags, or null: every row
  double uniform_shear_rate;              // s_nu (uniform mode)
  double u_bottom, u_top;                 // wall x-velocities
};

// One row of either step: point in[] and out[] at the step's slots (x offsets folded in),
// then the node update shared with the two-lattice pass (collide_and_bounce.hpp).
template <class L, class T, class A, bool per_node, bool trt, bool macro, bool bottom_wall, bool top_wall, bool odd>
[[gnu::flatten]] CAPSULE_LBM_FAST_CLONE_ATTR void in_place_row(const InPlaceFields<T>& a, int y, int z) {
  using B = MomentBasis<L>;
  const std::size_t np = a.rows.per_population();
  auto row_start = [&](int i, int yy, int zz) {
    return a.g + std::size_t(i) * np + a.rows.index(std::size_t(yy) + std::size_t(a.ny) * std::size_t((zz + a.nz) % a.nz), 0);
  };
  RowAccess<L, T, A> r;
  static_for<L::Q>([&](auto jj) __attribute__((always_inline)) {
    constexpr int j = jj;
    constexpr int o = B::opposite[j];
    constexpr int cx = L::c[j][0], cy = L::c[j][1], cz = L::c[j][2];
    if constexpr (!odd) {
      r.in[j] = row_start(j, y, z);
      r.out[j] = row_start(o, y, z);
    } else {
      constexpr bool arrives_from_wall = (bottom_wall && cy > 0) || (top_wall && cy < 0);  // x - c_j beyond
      if constexpr (arrives_from_wall) r.in[j] = row_start(j, y, z);
      else r.in[j] = row_start(o, y - cy, z - cz) - cx;
      constexpr bool leaves = (bottom_wall && cy < 0) || (top_wall && cy > 0);  // x + c_j beyond a wall
      if constexpr (leaves) r.out[j] = row_start(o, y, z);
      else r.out[j] = row_start(j, y + cy, z + cz) + cx;
    }
  });
  point_row_fields<per_node>(r, a, y, z);
  const int nx = a.nx;
#pragma omp simd
  for (int x = 0; x < nx; ++x)
    collide_and_bounce<L, T, A, SplitForcedCollision<L, A, trt>, per_node, macro, bottom_wall, top_wall>(r, x, x, x);
}

template <class L, class T, class A, bool per_node, bool trt, bool macro, bool odd>
inline void in_place_row_walls(const InPlaceFields<T>& a, int y, int z) {
  const bool bottom = (y == 0), top = (y == a.ny - 1);
  if (bottom && top) in_place_row<L, T, A, per_node, trt, macro, true, true, odd>(a, y, z);
  else if (bottom) in_place_row<L, T, A, per_node, trt, macro, true, false, odd>(a, y, z);
  else if (top) in_place_row<L, T, A, per_node, trt, macro, false, true, odd>(a, y, z);
  else in_place_row<L, T, A, per_node, trt, macro, false, false, odd>(a, y, z);
}

// The ghost copies around an odd step: to_ghosts = true before it (x = 0 -> slot nx for
// c_x = +1, x = nx-1 -> slot -1 for c_x = -1), false after it (back). Only the slots an odd
// step reaches through a ghost: those of rows whose source row y - c_y is inside the channel
// (at a wall the real slot carries the bounced population and must not be overwritten).
template <class L, class T>
inline void in_place_ghosts(const InPlaceFields<T>& a, long r, bool to_ghosts) {
  const std::size_t np = a.rows.per_population();
  const int nx = a.nx;
  const int y = int(r % a.ny);
  static_for<L::Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    constexpr int cx = L::c[i][0], cy = L::c[i][1];
    if constexpr (cx != 0) {
      const int ys = y - cy;
      if (ys >= 0 && ys < a.ny) {
        T* p = a.g + std::size_t(i) * np + a.rows.index(std::size_t(r), 0);
        const int real = cx > 0 ? 0 : nx - 1, ghost = cx > 0 ? nx : -1;
        if (to_ghosts) p[ghost] = p[real];
        else p[real] = p[ghost];
      }
    }
  });
}

template <class L, class T, class A, bool per_node, bool trt = false>
void in_place_stream_collide(const InPlaceFields<T>& a, bool odd) {
  const long rows = long(a.ny) * long(a.nz);
  const int ny = a.ny;
  const bool parallel = a.n >= parallel_threshold_nodes;
  auto row_pass = [&](long r, auto odd_c) {
    constexpr bool o = decltype(odd_c)::value;
    const int y = int(r % ny), z = int(r / ny);
    if (!a.macroscopic_rows || a.macroscopic_rows[r]) in_place_row_walls<L, T, A, per_node, trt, true, o>(a, y, z);
    else in_place_row_walls<L, T, A, per_node, trt, false, o>(a, y, z);
  };
  if (!odd) {
#pragma omp parallel for schedule(static) if (parallel)
    for (long r = 0; r < rows; ++r) row_pass(r, std::false_type{});
    return;
  }
#pragma omp parallel if (parallel)
  {
#pragma omp for schedule(static)
    for (long r = 0; r < rows; ++r) in_place_ghosts<L>(a, r, true);
#pragma omp for schedule(static)
    for (long r = 0; r < rows; ++r) row_pass(r, std::true_type{});
#pragma omp for schedule(static)
    for (long r = 0; r < rows; ++r) in_place_ghosts<L>(a, r, false);
  }
}

}  // namespace capsule::lbm
