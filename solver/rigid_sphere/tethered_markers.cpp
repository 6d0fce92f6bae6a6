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

namespace capsule::rigid_sphere {

namespace {

template <int Dim>
void run(const TetheredMarkers& s, RigidShellResult& result) {
  using Lattice = std::conditional_t<Dim == 2, lbm::D2Q9, lbm::D3Q19>;
  const auto start = std::chrono::steady_clock::now();
  const int nx = s.grid[0], ny = s.grid[1], nz = Dim == 3 ? s.grid[2] : 1;
  const double k = s.k, Omega = s.Omega, a = s.length, inside = s.inside;
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
    RigidShellRow r;
    r.kt = step * k;
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
    r.torque = T / s.torque_unit;
    r.stresslet = S / s.stresslet_unit;
    r.leakage = leak / (k * a);
    r.lag = lag / a;
    r.slip = slip / (k * a);
    r.slip_rms = std::sqrt(slip_rms) / (k * a);
    result.series.push_back(r);
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
    const double phi = Omega * step, cs = std::cos(phi), sn = std::sin(phi);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = A0[Dim * i] - c[0], y = A0[Dim * i + 1] - c[1];
      A[Dim * i] = c[0] + cs * x - sn * y;
      A[Dim * i + 1] = c[1] + sn * x + cs * y;
      if constexpr (Dim == 3) A[3 * i + 2] = A0[3 * i + 2];
    }
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

}  // namespace

void run_tethered_markers(const TetheredMarkers& setup, RigidShellResult& result) {
  if (setup.dim == 2) run<2>(setup, result);
  else if (setup.dim == 3) run<3>(setup, result);
  else throw std::invalid_argument(setup.name + ": dim must be 2 or 3, got " + std::to_string(setup.dim));
}

}  // namespace capsule::rigid_sphere
