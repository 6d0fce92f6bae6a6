// `capsule bench lbm`: speed of the fused stream-collide step against the memory roofline.
//
// Kernels (same process, same machine, same threads, so the ratio survives a busy machine):
//   baseline  baseline_stream_collide.hpp (full moment transform,
//             double populations, rho/u written and F read at every node);
//   double    Fluid's kernel (split collision, in-place AA streaming) in double precision;
//   double-2lat the same collision streamed between two lattices (shifted_stream_collide.hpp):
//             the in-place scheme's own gain is double / double-2lat;
//   single    the same in single precision (float populations f_i - w_i, float arithmetic);
//   ...-rows0 the same with no macroscopic row (Fluid::set_macroscopic_region({})): rho/u not
//             written, F not read -- a 3D member flags only the rows around the membrane,
//             ~10 % of them at a = 10, so it runs close to these rows.
//
// Bytes per node update: every byte the memory system moves, write-allocate reads included (a
// line written without being read first is read in as well), so that the bandwidth below is
// counted the same way and no kernel can exceed it from memory:
//   populations read Q*s and written Q*s (s = 8 or 4 B; in place, AA pattern: the lines written
//   were just read, no write-allocate); the two-lattice kernels (baseline, double-2lat) write a
//   second lattice: + Q*8 write-allocate; force read D*8; density and velocity written (D+1)*8
//   plus their write-allocate (D+1)*8 (both double in either precision; none in rows0 rows).
//   D3Q19: double 392 B, single 240, rows0 304 / 152, two lattices 544; D2Q9: 208 / 136, 280.
// Bandwidth: a STREAM triad a[i] = b[i] + s c[i] over arrays 4x the last-level cache, counted
// as 32 B per element (b and c read, a written and write-allocated), best of several
// repetitions, with the same thread count.
// Roofline fraction = MLUPS * 1e6 * bytes / bandwidth.
#include "solver/bench/lbm_bench.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "solver/bench/baseline_stream_collide.hpp"
#include "solver/lbm/equilibrium.hpp"
#include "solver/lbm/fluid.hpp"

namespace capsule::lbm {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// STREAM triad bandwidth in bytes/s (32 B per element, write-allocate counted), best of `repeats`.
double triad_bandwidth(int threads, int repeats) {
  const std::size_t n = std::size_t(1) << 24;  // 3 x 128 MiB, 12x a 32 MiB L3
  std::vector<double> a(n), b(n), c(n);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {  // first touch by the threads that compute
    a[i] = 0.0;
    b[i] = double(i % 7);
    c[i] = double(i % 5);
  }
  const double scalar = 3.0;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + scalar * c[i];
    best = std::min(best, seconds_since(t0));
  }
  if (a[n / 3] != b[n / 3] + scalar * c[n / 3]) std::printf("triad kernel failed\n");
  return 32.0 * double(n) / best;
}

enum class Kernel { baseline, double_two_lattice, double_full, double_rows0, single_full, single_rows0 };

const char* kernel_name(Kernel k) {
  switch (k) {
    case Kernel::baseline: return "baseline";
    case Kernel::double_two_lattice: return "double-2lat";
    case Kernel::double_full: return "double";
    case Kernel::double_rows0: return "double-rows0";
    case Kernel::single_full: return "single";
    case Kernel::single_rows0: return "single-rows0";
  }
  return "?";
}

template <class L>
double bytes_per_update(Kernel k) {
  const bool single = k == Kernel::single_full || k == Kernel::single_rows0;
  const bool rows0 = k == Kernel::double_rows0 || k == Kernel::single_rows0;
  const bool two_lattices = k == Kernel::baseline || k == Kernel::double_two_lattice;
  const double populations = (single ? 4.0 : 8.0) * 2 * L::Q + (two_lattices ? 8.0 * L::Q : 0.0);
  return populations + (rows0 ? 0.0 : 8.0 * (L::D + 2 * (L::D + 1)));
}

// The baseline kernel on its own arrays (it needs unshifted double populations).
template <class L>
struct BaselineFluid {
  int nx, ny, nz;
  std::size_t n;
  PaddedRows rows;
  std::vector<double> f, f_next, force, velocity, density;
  BaselineFluid(int nx_, int ny_, int nz_)
      : nx(nx_), ny(ny_), nz(nz_), n(std::size_t(nx_) * ny_ * nz_), rows(std::size_t(nx_), std::size_t(ny_) * nz_),
        f(L::Q * rows.per_population(), 0.0), f_next(f.size(), 0.0), force(3 * n, 0.0), velocity(3 * n, 0.0),
        density(n, 1.0) {
    for (int z = 0; z < nz; ++z)
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
          double feq[L::Q];
          equilibrium<L>(1.0, {0.04 * ((y + 0.5) / ny - 0.5), 0.0, 0.0}, feq);
          for (int i = 0; i < L::Q; ++i) f[i * rows.per_population() + rows.index(y + std::size_t(ny) * z, x)] = feq[i];
        }
  }
  void step(double s_nu) {
    baseline::StreamCollideFields a{nx, ny, nz, n, rows, f.data(), f_next.data(), force.data(), velocity.data(),
                                    density.data(), nullptr, s_nu, -0.02, 0.02};
    baseline::stream_collide<L, false>(a);
    f.swap(f_next);
  }
};

struct Row {
  const char* lattice;
  Kernel kernel;
  int nx, ny, nz, threads, steps;
  double mlups, bandwidth;
  double mlups_per_cpu_second;  // updates per second of process CPU time (robust to a busy machine)
};

template <class Stepper>
void time_steps(Stepper&& step, int steps, double& best, double& best_cpu) {
  const int warmup = std::max(2, steps / 10);
  for (int s = 0; s < warmup; ++s) step();
  best = 1e30, best_cpu = 1e30;
  // Three timed blocks, the best one reported (others may share the machine).
  for (int block = 0; block < 3; ++block) {
    const auto t0 = Clock::now();
    const std::clock_t c0 = std::clock();
    for (int s = 0; s < steps; ++s) step();
    best = std::min(best, seconds_since(t0));
    best_cpu = std::min(best_cpu, double(std::clock() - c0) / CLOCKS_PER_SEC);
  }
}

template <class L>
Row measure(const char* name, Kernel kernel, int nx, int ny, int nz, int threads, int steps, double bandwidth) {
  omp_set_num_threads(threads);
  double best = 0, best_cpu = 0;
  const double nu = 0.1;
  if (kernel == Kernel::baseline) {
    BaselineFluid<L> fluid(nx, ny, nz);
    time_steps([&] { fluid.step(shear_rate_from_viscosity(nu)); }, steps, best, best_cpu);
  } else {
    const bool single = kernel == Kernel::single_full || kernel == Kernel::single_rows0;
    Fluid<L> fluid(nx, ny, nz, nu, single ? Precision::single_precision : Precision::double_precision,
                   kernel == Kernel::double_two_lattice ? Streaming::two_lattice : Streaming::in_place);
    fluid.set_wall_velocity(-0.02, 0.02);
    fluid.initialise_velocity([&](double, double y, double) {
      return std::array<double, 3>{0.04 * (y / ny - 0.5), 0.0, 0.0};
    });
    if (kernel == Kernel::double_rows0 || kernel == Kernel::single_rows0) fluid.set_macroscopic_region({});
    time_steps([&] { fluid.step(); }, steps, best, best_cpu);
  }
  const double updates = double(nx) * ny * nz * steps;
  return {name, kernel, nx, ny, nz, threads, steps, updates / best / 1e6, bandwidth, updates / best_cpu / 1e6};
}

void print(const Row& r, double bytes, double baseline_mlups) {
  char grid[64];
  if (r.nz > 1) std::snprintf(grid, sizeof grid, "%dx%dx%d", r.nx, r.ny, r.nz);
  else std::snprintf(grid, sizeof grid, "%dx%d", r.nx, r.ny);
  const double achieved = r.mlups * 1e6 * bytes;
  std::printf("%-6s %-11s %-13s %7d %9.1f %6.0f %9.2f %10.2f %8.0f%% %11.1f %7.2f\n", r.lattice, grid, kernel_name(r.kernel),
              r.threads, r.mlups, bytes, achieved / 1e9, r.bandwidth / 1e9, 100.0 * achieved / r.bandwidth,
              r.mlups_per_cpu_second, r.mlups / baseline_mlups);
  std::fflush(stdout);
}

template <class L>
void measure_group(const char* name, int nx, int ny, int nz, int threads, int steps, double bw, bool rows0) {
  std::vector<Kernel> kernels{Kernel::baseline, Kernel::double_two_lattice, Kernel::double_full};
  if (rows0) kernels.push_back(Kernel::double_rows0);
  kernels.push_back(Kernel::single_full);
  if (rows0) kernels.push_back(Kernel::single_rows0);
  double base = 0;
  for (Kernel k : kernels) {
    const Row r = measure<L>(name, k, nx, ny, nz, threads, steps, bw);
    if (k == Kernel::baseline) base = r.mlups;
    print(r, bytes_per_update<L>(k), base);
  }
}

}  // namespace

int bench_lbm(bool quick, int max_threads) {
  const int all = max_threads > 0 ? max_threads : omp_get_max_threads();
  const int saved = omp_get_max_threads();
  std::vector<int> thread_counts{1};
  if (all > 1) thread_counts.push_back(all);
  const int scale = quick ? 1 : 5;

  std::printf("LBM benchmark (fused MRT stream-collide, two lattices, SoA; kernels: see solver/bench/lbm_bench.cpp)\n");
  std::printf("bytes/update: all traffic, write-allocate included: populations read+write (+ the second lattice's\n"
              " write-allocate), force read, rho+u write + write-allocate (D3Q19 double 392, single 240,\n"
              " rows0 = populations only 304 / 152, two lattices 544; D2Q9 208 / 136, two lattices 280)\n");
  std::printf("bandwidth: STREAM triad (32 B/element, write-allocate counted), same threads\n");
  std::printf("x base: MLUPS over the baseline kernel's (full moment transform, two lattices) in this run\n");
  double load[3] = {0.0, 0.0, 0.0};
  if (getloadavg(load, 3) == 3)
    std::printf("machine load average at start: %.2f (1 min), %d hardware threads used at most\n", load[0], all);
  std::printf("(grids that fit in cache can exceed 100%% of the memory roofline; MLUPS/cpu-s divides by\n"
              " process CPU time, all threads, spin-waits included: on a busy machine it shows the kernel's\n"
              " own speed better than wall-clock MLUPS)\n\n");
  std::printf("%-6s %-11s %-13s %7s %9s %6s %9s %10s %9s %11s %7s\n", "model", "grid", "kernel", "threads", "MLUPS", "B/upd",
              "GB/s used", "triad GB/s", "roofline", "MLUPS/cpu-s", "x base");
  for (int t : thread_counts) {
    const double bw = triad_bandwidth(t, quick ? 5 : 10);
    measure_group<D2Q9>("D2Q9", 160, 120, 1, t, 200 * scale, bw, false);
    measure_group<D2Q9>("D2Q9", 2048, 2048, 1, t, 4 * scale, bw, false);
    measure_group<D3Q19>("D3Q19", 100, 100, 80, t, 4 * scale, bw, true);
  }
  omp_set_num_threads(saved);
  return 0;
}

}  // namespace capsule::lbm
