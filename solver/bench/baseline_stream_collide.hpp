#pragma once
// The benchmark's baseline: the fused pass with the full moment transform of collision.hpp on
// unshifted double populations, rho/u written and F read at every node, between two lattices.
// `capsule bench lbm` times it beside the kernels Fluid runs (the `baseline` rows, same process,
// same machine); Fluid does not run it, and no test does (the kernels Fluid runs are tested
// against each other and against the reference MRT collision: tests/solver/lbm/in_place_test.cpp,
// tests/solver/lbm/split_collision_test.cpp). The node update is the shared one
// (solver/lbm/collide_and_bounce.hpp). The row function has AVX2 and baseline x86-64 clones;
// "avx2" has no FMA, so both do the same IEEE operations per node, on wider vectors.
#include <cstddef>

#include "solver/lbm/collide_and_bounce.hpp"
#include "solver/lbm/collision.hpp"
#include "solver/lbm/padded_rows.hpp"
#include "solver/lbm/parallel.hpp"

// AVX2 and baseline clones on x86-64 (GNU ifunc); one plain version elsewhere.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__linux__)
#define CAPSULE_LBM_KERNEL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define CAPSULE_LBM_KERNEL_CLONES
#endif

namespace capsule::lbm::baseline {

struct StreamCollideFields {
  int nx, ny, nz;
  std::size_t n;              // nodes
  PaddedRows rows;            // layout of the population arrays
  const double* f;            // Q*rows.per_population(), level n
  double* f_next;             // the same, level n+1
  const double* force;        // 3*n
  double* velocity;           // 3*n
  double* density;            // n
  const double* shear_rate;   // n, per-node s_nu (per-node mode only)
  double uniform_shear_rate;  // s_nu (uniform mode)
  double u_bottom, u_top;     // wall x-velocities
};

// The full MRT collision (collision.hpp) in the shared node update.
template <class L>
struct FullCollision {
  [[gnu::always_inline]] static inline void collide(double (&f)[L::Q], const double (&force)[3], double s_nu, double& rho,
                                                    double (&u)[3]) {
    Collision<L>::collide(f, force, s_nu, rho, u);
  }
};

// flatten: inline the whole collision (lambdas included) so the x loop vectorises.
template <class L, bool per_node, bool bottom_wall, bool top_wall>
[[gnu::flatten]] CAPSULE_LBM_KERNEL_CLONES void stream_collide_row(const StreamCollideFields& a, int y, int z) {
  RowAccess<L, double, double> r;
  point_two_lattice_row<L, double, double, PaddedRows, bottom_wall, top_wall>(r, a.f, a.f_next, a.rows,
                                                                              a.rows.per_population(), y, z, a.ny, a.nz);
  point_row_fields<per_node>(r, a, y, z);
  const int nx = a.nx;
#pragma omp simd
  for (int x = 0; x < nx; ++x)
    collide_and_bounce<L, double, double, FullCollision<L>, per_node, true, bottom_wall, top_wall>(r, x, x - 1, x + 1);
  wrap_x_ghosts<L, double, double, bottom_wall, top_wall>(r, nx);
}

template <class L, bool per_node>
void stream_collide(const StreamCollideFields& a) {
  const long rows = long(a.ny) * long(a.nz);
  const int ny = a.ny;
  // Small grids (tests, 2D toy runs) stay on one thread: a parallel region costs
  // more than the work below a few thousand nodes.
  const bool parallel = a.n >= parallel_threshold_nodes;
#pragma omp parallel for schedule(static) if (parallel)
  for (long r = 0; r < rows; ++r) {
    const int y = int(r % ny), z = int(r / ny);
    const bool bottom = (y == 0), top = (y == ny - 1);
    if (bottom && top) stream_collide_row<L, per_node, true, true>(a, y, z);
    else if (bottom) stream_collide_row<L, per_node, true, false>(a, y, z);
    else if (top) stream_collide_row<L, per_node, false, true>(a, y, z);
    else stream_collide_row<L, per_node, false, false>(a, y, z);
  }
}

}  // namespace capsule::lbm::baseline
