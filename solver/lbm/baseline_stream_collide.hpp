#pragma once
// BASELINE: the fused kernel as it was before the kernel rewrite of 2026-12-01 (full moment transform of
// collision.hpp, unshifted double populations, rho/u written and F read at every node).
// Fluid no longer runs it; `capsule bench lbm` times it beside the new kernel (the
// `baseline` rows, same process, same machine); no test runs it (the kernels Fluid runs are
// tested against each other and against the reference MRT collision:
// tests/solver/lbm/in_place_test.cpp, tests/solver/lbm/split_collision_test.cpp). Namespace lbm::baseline.
//
// One fused pass: collide every node (collision.hpp) and push the post-collision
// populations to their neighbours in the second lattice (periodic in x and z,
// half-way bounce-back with the moving-wall correction at y = 0 and y = ny).
// Templates choose the lattice, the viscosity mode and the wall rows once, so the
// node loop has no branches; every (padded) x-row is one `omp simd` loop.
// The row kernel is compiled twice (target_clones: AVX2 and baseline x86-64) and the
// loader picks the clone for the CPU. The "avx2" target has no FMA, so both clones do
// the same IEEE operations per node, only on wider vectors.
#include <cstddef>

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

// flatten: inline the whole collision (lambdas included) so the x loop vectorises.
template <class L, bool per_node, bool bottom_wall, bool top_wall>
[[gnu::flatten]] CAPSULE_LBM_KERNEL_CLONES void stream_collide_row(const StreamCollideFields& a, int y, int z) {
  constexpr int Q = L::Q;
  using B = MomentBasis<L>;
  const int nx = a.nx;
  const std::size_t n = a.n;
  const std::size_t np = a.rows.per_population();
  const std::size_t row = std::size_t(y) + std::size_t(a.ny) * std::size_t(z);
  const std::size_t base = std::size_t(nx) * row;  // unpadded fields
  const std::size_t pbase = a.rows.index(row, 0);  // this row in a population array

  const double* in[Q];
  double* out[Q];
  static_for<Q>([&](auto ii) __attribute__((always_inline)) {
    constexpr int i = ii;
    in[i] = a.f + std::size_t(i) * np + pbase;
    constexpr int cy = L::c[i][1];
    constexpr bool leaves = (bottom_wall && cy < 0) || (top_wall && cy > 0);
    if constexpr (leaves) {
      out[i] = a.f_next + std::size_t(B::opposite[i]) * np + pbase;  // bounced back into this node
    } else {
      const int yd = y + cy;
      const int zd = (z + L::c[i][2] + a.nz) % a.nz;
      out[i] = a.f_next + std::size_t(i) * np + a.rows.index(std::size_t(yd) + std::size_t(a.ny) * std::size_t(zd), 0);
    }
  });
  const double* force[3] = {a.force + base, a.force + n + base, a.force + 2 * n + base};
  double* vel[3] = {a.velocity + base, a.velocity + n + base, a.velocity + 2 * n + base};
  double* rho_out = a.density + base;
  const double* s_node = per_node ? a.shear_rate + base : nullptr;
  const double s_uniform = a.uniform_shear_rate;
  const double u_bottom = a.u_bottom, u_top = a.u_top;

  // xm, xp: destination x of populations with c_x = -1, +1 (periodic).
  auto node = [&](int x, int xm, int xp) {
    double f[Q];
    static_for<Q>([&](auto i) __attribute__((always_inline)) { f[i] = in[i][x]; });
    double F[3] = {0.0, 0.0, 0.0};
    static_for<L::D>([&](auto d) __attribute__((always_inline)) { F[d] = force[d][x]; });
    double s_nu;
    if constexpr (per_node) s_nu = s_node[x];
    else s_nu = s_uniform;
    double rho, u[3];
    Collision<L>::collide(f, F, s_nu, rho, u);
    rho_out[x] = rho;
    static_for<L::D>([&](auto d) __attribute__((always_inline)) { vel[d][x] = u[d]; });
    static_for<Q>([&](auto ii) __attribute__((always_inline)) {
      constexpr int i = ii;
      constexpr int cx = L::c[i][0];
      constexpr int cy = L::c[i][1];
      if constexpr (bottom_wall && cy < 0) {
        // Moving wall: f_opp = f*_i - 6 w_i rho c_i.u_wall  (6 w_i = W_i/6).
        out[i][x] = f[i] - (L::weight_numerator[i] * cx / 6.0) * rho * u_bottom;
      } else if constexpr (top_wall && cy > 0) {
        out[i][x] = f[i] - (L::weight_numerator[i] * cx / 6.0) * rho * u_top;
      } else if constexpr (cx > 0) {
        out[i][xp] = f[i];
      } else if constexpr (cx < 0) {
        out[i][xm] = f[i];
      } else {
        out[i][x] = f[i];
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
