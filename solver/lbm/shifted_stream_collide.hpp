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
// once, so the x loop has no branches; every (padded) x-row is one `omp simd` loop over the
// node update of collide_and_bounce.hpp.
#include <cstddef>

#include "solver/lbm/collide_and_bounce.hpp"
#include "solver/lbm/padded_rows.hpp"
#include "solver/lbm/parallel.hpp"
#include "solver/lbm/split_collision.hpp"

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

// The split collision (split_collision.hpp), always forced (collide_and_bounce.hpp says why).
template <class L, class A, bool trt>
struct SplitForcedCollision {
  [[gnu::always_inline]] static inline void collide(A (&g)[L::Q], const A (&force)[3], A s_nu, A& rho, A (&u)[3]) {
    SplitCollision<L, A>::template collide<true, trt>(g, force, s_nu, rho, u);
  }
};

// flatten: inline the whole collision (lambdas included) so the x loop vectorises.
template <class L, class T, class A, bool per_node, bool trt, bool macro, bool bottom_wall, bool top_wall>
[[gnu::flatten]] CAPSULE_LBM_FAST_CLONE_ATTR void shifted_stream_collide_row(const ShiftedFields<T>& a, int y, int z) {
  RowAccess<L, T, A> r;
  point_two_lattice_row<L, T, A, PaddedRows, bottom_wall, top_wall>(r, a.g, a.g_next, a.rows, a.rows.per_population(), y,
                                                                      z, a.ny, a.nz);
  point_row_fields<per_node>(r, a, y, z);
  const int nx = a.nx;
  // The whole row in one vector loop: x - 1 = -1 and x + 1 = nx land in the ghost slots.
#pragma omp simd
  for (int x = 0; x < nx; ++x)
    collide_and_bounce<L, T, A, SplitForcedCollision<L, A, trt>, per_node, macro, bottom_wall, top_wall>(r, x, x - 1, x + 1);
  wrap_x_ghosts<L, T, A, bottom_wall, top_wall>(r, nx);
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
