#include "solver/rigid_sphere/tethered_markers.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "solver/ib/delta.hpp"
#include "solver/ib/grid.hpp"
#include "solver/ib/interpolation.hpp"
#include "solver/lbm/fluid.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/precision.hpp"
#include "solver/lbm/refinement/refined_fluid.hpp"

namespace capsule::rigid_sphere {

namespace {

// One row from the markers (positions X, this step's force F where it acted, velocity U, anchors
// A) about the centre c; leak is the fluid's largest departure from the rigid rotation inside.
template <int Dim>
RigidShellRow marker_row(const TetheredMarkers& s, const double* c, double kt, const std::vector<double>& X,
                         const std::vector<double>& F, const std::vector<double>& U, const std::vector<double>& A,
                         double leak) {
  const double k = s.k, Omega = s.Omega, a = s.length;
  const std::size_t n = X.size() / Dim;
  RigidShellRow r;
  r.kt = kt;
  double T = 0, S = 0, lag = 0, slip = 0, slip_rms = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = X[Dim * i] - c[0], y = X[Dim * i + 1] - c[1];
    double s2 = std::pow(U[Dim * i] + Omega * y, 2) + std::pow(U[Dim * i + 1] - Omega * x, 2);
    if constexpr (Dim == 3) s2 += std::pow(U[3 * i + 2], 2);
    slip = std::max(slip, std::sqrt(s2));
    slip_rms += s2 / n;
    T += x * F[Dim * i + 1] - y * F[Dim * i];
    S -= 0.5 * (x * F[Dim * i + 1] + y * F[Dim * i]);
    if constexpr (Dim == 3)
      lag = std::max(lag, std::hypot(A[3 * i] - X[3 * i], A[3 * i + 1] - X[3 * i + 1], A[3 * i + 2] - X[3 * i + 2]));
    else
      lag = std::max(lag, std::hypot(A[2 * i] - X[2 * i], A[2 * i + 1] - X[2 * i + 1]));
  }
  r.torque = T / s.torque_unit;
  r.stresslet = S / s.stresslet_unit;
  r.leakage = leak / (k * a);
  r.lag = lag / a;
  r.slip = slip / (k * a);
  r.slip_rms = std::sqrt(slip_rms) / (k * a);
  return r;
}

// The anchors at time step t: A0 turned by Omega t about z through c.
template <int Dim>
void turn_anchors(const std::vector<double>& A0, const double* c, double phi, std::vector<double>& A) {
  const double cs = std::cos(phi), sn = std::sin(phi);
  for (std::size_t i = 0; i < A0.size() / Dim; ++i) {
    const double x = A0[Dim * i] - c[0], y = A0[Dim * i + 1] - c[1];
    A[Dim * i] = c[0] + cs * x - sn * y;
    A[Dim * i + 1] = c[1] + sn * x + cs * y;
    if constexpr (Dim == 3) A[3 * i + 2] = A0[3 * i + 2];
  }
}

template <int Dim>
void run(const TetheredMarkers& s, RigidShellResult& result) {
  using Lattice = std::conditional_t<Dim == 2, lbm::D2Q9, lbm::D3Q19>;
  const auto start = std::chrono::steady_clock::now();
  const int nx = s.grid[0], ny = s.grid[1], nz = Dim == 3 ? s.grid[2] : 1;
  const double k = s.k, Omega = s.Omega, inside = s.inside;
  const ib::Grid grid{nx, ny, nz};
  const ib::Delta delta = s.delta;
  lbm::Fluid<Lattice> fluid(nx, ny, nz, s.nu, s.precision);
  const double H = ny;
  fluid.initialise_velocity([&](double, double y, double) { return std::array<double, 3>{k * (y - 0.5 * H), 0.0, 0.0}; });

  const double c[3] = {0.5 * nx, 0.5 * ny, 0.5 * nz};
  const std::size_t n = s.anchors.size() / Dim;
  const std::vector<double>& A0 = s.anchors;
  std::vector<double> X = A0, F(Dim * n), U(Dim * n), A(Dim * n);

  auto row = [&](long step) {
    double leak = 0;
    if (inside > 0) {
      for (int kz = 0; kz < nz; ++kz)
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i) {
            const double x = i + 0.5 - c[0], y = j + 0.5 - c[1];
            const std::size_t node = grid.index(i, j, kz);
            // against the rigid rotation Omega z x r = (-Omega y, Omega x, 0)
            if constexpr (Dim == 3) {
              const double z = kz + 0.5 - c[2];
              if (x * x + y * y + z * z >= inside * inside) continue;
              leak = std::max(leak, std::hypot(fluid.velocity(0)[node] + Omega * y, fluid.velocity(1)[node] - Omega * x,
                                               fluid.velocity(2)[node]));
            } else {
              if (x * x + y * y >= inside * inside) continue;
              leak = std::max(leak, std::hypot(fluid.velocity(0)[node] + Omega * y, fluid.velocity(1)[node] - Omega * x));
            }
          }
    }
    result.series.push_back(marker_row<Dim>(s, c, step * k, X, F, U, A, leak));
  };

  const long steps = static_cast<long>(std::ceil(s.kt / k));
  const long every = std::max(1L, static_cast<long>(std::lround(s.every / k)));
  double* p[Dim];
  const double* u[Dim];
  for (int d = 0; d < Dim; ++d) {
    p[d] = fluid.force(d);
    u[d] = fluid.velocity(d);
  }
  for (long step = 0; step < steps; ++step) {
    turn_anchors<Dim>(A0, c, Omega * step, A);
    for (std::size_t i = 0; i < Dim * n; ++i) F[i] = s.gain * (A[i] - X[i]);
    fluid.clear_force();
    ib::spread<Dim>(grid, X.data(), F.data(), n, p, delta);  // (21)
    fluid.set_wall_velocity(-0.5 * k * H, 0.5 * k * H);      // (1)
    fluid.step();
    if (!std::isfinite(u[0][grid.index(nx / 2, ny / 2, nz / 2)]))
      throw std::runtime_error(s.name + ": the fluid blew up at kt = " + std::to_string(step * k));
    ib::interpolate<Dim>(grid, u, X.data(), n, U.data(), delta);    // (19)
    if ((step + 1) % every == 0 || step + 1 == steps) row(step + 1);  // F, X, U: this step's force, where it acted
    ib::advance<Dim>(X.data(), U.data(), n, 1.0);                    // (20)
  }
  result.steps = steps;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The block of a refined run: the anchors' extent (fine lattice units of the whole channel,
// halved into coarse cells) plus margin coarse cells on each side, on the refined axes.
template <int Dim>
lbm::refinement::BlockExtent block_around(const TetheredMarkers& s) {
  lbm::refinement::BlockExtent e;
  for (int d = 0; d < Dim; ++d) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = d; i < s.anchors.size(); i += Dim) lo = std::min(lo, s.anchors[i]), hi = std::max(hi, s.anchors[i]);
    e.begin[d] = static_cast<int>(std::floor(0.5 * lo)) - s.refine_margin;
    e.end[d] = static_cast<int>(std::ceil(0.5 * hi)) + s.refine_margin;
  }
  return e;
}

// The markers in a fluid refined by a factor 2 around them (solver/lbm/refinement/refined_fluid.hpp),
// the immersed boundary on the fine lattice at its time step: `s` is the uniform fine lattice's
// setup (grid, anchors, nu and k per fine step), so the rows compare with run<Dim>(s). The coarse
// lattice has half the nodes per axis, half the lattice viscosity and twice the shear rate per
// step; the fine block covers the anchors plus s.refine_margin coarse cells.
template <int Dim>
void run_refined(const TetheredMarkers& s, RigidShellResult& result) {
  using Lattice = std::conditional_t<Dim == 2, lbm::D2Q9, lbm::D3Q19>;
  const auto start = std::chrono::steady_clock::now();
  for (int d = 0; d < Dim; ++d)
    if (s.grid[d] % 2 != 0)
      throw std::invalid_argument(s.name + ": a refined run needs an even fine grid, axis " + std::to_string(d) +
                                  " has " + std::to_string(s.grid[d]));
  if (s.delta != ib::Delta::peskin4 && s.delta != ib::Delta::cosine && s.delta != ib::Delta::roma3)
    throw std::invalid_argument(s.name + ": a refined run takes peskin4, roma3 or cosine");
  const int ncx = s.grid[0] / 2, ncy = s.grid[1] / 2, ncz = Dim == 3 ? s.grid[2] / 2 : 1;
  const double k = s.k, Omega = s.Omega;  // per fine step
  lbm::refinement::RefinedFluid<Lattice> fluid(ncx, ncy, ncz, 0.5 * s.nu, block_around<Dim>(s));
  // In coarse units the Couette flow is u = k_c (y_c - H_c / 2), k_c = 2 k: the same velocities.
  fluid.initialise_velocity(
      [&](double, double y, double) { return std::array<double, 3>{2.0 * k * (y - 0.5 * ncy), 0.0, 0.0}; });
  const auto fg = fluid.fine_grid();
  const ib::Grid grid{fg[0], fg[1], fg[2]};
  // A position of the whole fine channel on the block's fine lattice: x_f = 2 (x / 2 - first).
  double shift[3] = {0, 0, 0};
  for (int d = 0; d < Dim; ++d) shift[d] = fluid.to_fine(d, 0.0);
  const double c[3] = {0.5 * s.grid[0], 0.5 * s.grid[1], 0.5 * (Dim == 3 ? s.grid[2] : 1)};
  const std::size_t n = s.anchors.size() / Dim;
  const std::vector<double>& A0 = s.anchors;
  std::vector<double> X = A0, F(Dim * n), U(Dim * n), A(Dim * n), Xb(Dim * n);
  double* p[Dim];
  const double* u[Dim];
  for (int d = 0; d < Dim; ++d) {
    p[d] = fluid.fine_force(d);
    u[d] = fluid.fine_velocity(d);
  }
  const auto on_block = [&] {
    for (std::size_t i = 0; i < Dim * n; ++i) Xb[i] = X[i] + shift[i % Dim];
  };
  const long coarse_steps = static_cast<long>(std::ceil(0.5 * s.kt / k));
  const long every = std::max(1L, static_cast<long>(std::lround(s.every / k)));
  long t = 0;  // fine steps done
  for (long step = 0; step < coarse_steps; ++step) {
    fluid.set_wall_velocity(-k * ncy, k * ncy);  // -+ k_c H_c / 2 (1), coarse units
    fluid.step(
        [&](int) {
          turn_anchors<Dim>(A0, c, Omega * t, A);
          for (std::size_t i = 0; i < Dim * n; ++i) F[i] = s.gain * (A[i] - X[i]);
          for (int d = 0; d < Dim; ++d) std::fill(p[d], p[d] + grid.size(), 0.0);
          on_block();
          ib::spread<Dim>(grid, Xb.data(), F.data(), n, p, s.delta);  // (21), fine units
        },
        [&](int) {
          if (!std::isfinite(u[0][grid.index(fg[0] / 2, fg[1] / 2, fg[2] / 2)]))
            throw std::runtime_error(s.name + ": the fluid blew up at kt = " + std::to_string(t * k));
          ib::interpolate<Dim>(grid, u, Xb.data(), n, U.data(), s.delta);  // (19)
          ++t;
          if (t % every == 0 || t == 2 * coarse_steps) result.series.push_back(marker_row<Dim>(s, c, t * k, X, F, U, A, 0.0));
          ib::advance<Dim>(X.data(), U.data(), n, 1.0);  // (20), one fine step
        });
  }
  result.steps = t;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void run_tethered_markers(const TetheredMarkers& setup, RigidShellResult& result) {
  if (setup.refine_margin > 0) {
    if (setup.dim == 2) run_refined<2>(setup, result);
    else if (setup.dim == 3) run_refined<3>(setup, result);
    else throw std::invalid_argument(setup.name + ": dim must be 2 or 3, got " + std::to_string(setup.dim));
    return;
  }
  if (setup.dim == 2) run<2>(setup, result);
  else if (setup.dim == 3) run<3>(setup, result);
  else throw std::invalid_argument(setup.name + ": dim must be 2 or 3, got " + std::to_string(setup.dim));
}

}  // namespace capsule::rigid_sphere
