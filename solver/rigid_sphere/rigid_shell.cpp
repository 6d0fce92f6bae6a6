#include "solver/rigid_sphere/rigid_shell.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <ostream>
#include <stdexcept>

#include "solver/ib/delta.hpp"
#include "solver/ib/grid.hpp"
#include "solver/ib/interpolation.hpp"
#include "solver/lbm/fluid.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/precision.hpp"
#include "solver/membrane3d/mesh.hpp"
#include "solver/membrane3d/shapes.hpp"

namespace capsule::rigid_sphere {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("rigid shell: " + what);
}

}  // namespace

void validate(const RigidShellOptions& o) {
  require(o.a >= 2 && o.a <= 64, "a must be in [2, 64] lattice units, got " + std::to_string(o.a));
  const double r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  require(r_m >= 0.5 * o.a && r_m <= 1.5 * o.a, "marker_radius must be in [a/2, 3a/2], got " + std::to_string(o.marker_radius));
  require(o.level >= 1 && o.level <= 6, "level must be in [1, 6], got " + std::to_string(o.level));
  for (double d : o.domain) require(d >= 3 && d <= 40, "each domain side must be in [3, 40] a, got " + std::to_string(d));
  require(o.Re > 0 && o.Re <= 1, "Re must be in (0, 1], got " + std::to_string(o.Re));
  require(o.tau > 0.5 && o.tau <= 5, "tau must be in (0.5, 5], got " + std::to_string(o.tau));
  require(std::abs(o.spin) <= 2, "spin must be in [-2, 2] (units of k), got " + std::to_string(o.spin));
  require(o.kt > 0 && o.kt <= 100, "kt must be in (0, 100], got " + std::to_string(o.kt));
  require(o.gain > 0 && o.gain <= 1, "gain must be in (0, 1], got " + std::to_string(o.gain));
  require(o.every > 0 && o.every <= o.kt, "every must be in (0, kt], got " + std::to_string(o.every));
  ib::kernel_from_name(o.kernel);
  lbm::precision_from_name(o.precision);
}

RigidShellResult run_rigid_shell(const RigidShellOptions& o) {
  validate(o);
  const auto start = std::chrono::steady_clock::now();
  const double a = o.a, r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  const double nu = (o.tau - 0.5) / 3.0, mu = nu;  // (8), rho = 1
  const double k = o.Re * nu / (a * a);
  const double Omega = o.spin * k;
  RigidShellResult result;
  for (int d = 0; d < 3; ++d) result.grid[d] = static_cast<int>(std::lround(o.domain[d] * a));
  const int nx = result.grid[0], ny = result.grid[1], nz = result.grid[2];
  const ib::Grid grid{nx, ny, nz};
  const ib::Kernel kernel = ib::kernel_from_name(o.kernel);
  lbm::Fluid<lbm::D3Q19> fluid(nx, ny, nz, nu, lbm::precision_from_name(o.precision));
  const double H = ny;
  fluid.initialise_velocity([&](double, double y, double) { return std::array<double, 3>{k * (y - 0.5 * H), 0.0, 0.0}; });

  const membrane3d::Vec3 c(0.5 * nx, 0.5 * ny, 0.5 * nz);
  membrane3d::Mesh shell = membrane3d::sphere_mesh(membrane3d::unit_icosphere(o.level), r_m);
  const std::size_t n = shell.x.size();
  std::vector<double> A0(3 * n), X(3 * n), F(3 * n), U(3 * n), A(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) A0[3 * i + d] = X[3 * i + d] = shell.x[i](d) + c(d);

  // Unbounded values: torque 4 pi mu a^3 k (1 + 2 spin), stresslet (10/3) pi mu a^3 k.
  const double torque_unit = 4.0 * std::numbers::pi * mu * a * a * a * k;
  const double stresslet_unit = (10.0 / 3.0) * std::numbers::pi * mu * a * a * a * k;
  result.torque_exact = 1.0 + 2.0 * o.spin;
  const double inside = r_m - 2.5;  // nodes deeper than the kernel's reach (2) plus half a node

  auto row = [&](long step) {
    RigidShellRow r;
    r.kt = step * k;
    double T = 0, S = 0, lag = 0, slip = 0, slip_rms = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = X[3 * i] - c(0), y = X[3 * i + 1] - c(1);
      const double s2 = std::pow(U[3 * i] + Omega * y, 2) + std::pow(U[3 * i + 1] - Omega * x, 2) + std::pow(U[3 * i + 2], 2);
      slip = std::max(slip, std::sqrt(s2));
      slip_rms += s2 / n;
      T += x * F[3 * i + 1] - y * F[3 * i];
      S -= 0.5 * (x * F[3 * i + 1] + y * F[3 * i]);
      lag = std::max(lag, std::hypot(A[3 * i] - X[3 * i], A[3 * i + 1] - X[3 * i + 1], A[3 * i + 2] - X[3 * i + 2]));
    }
    double leak = 0;
    if (inside > 0) {
      for (int kz = 0; kz < nz; ++kz)
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i) {
            const double x = i + 0.5 - c(0), y = j + 0.5 - c(1), z = kz + 0.5 - c(2);
            if (x * x + y * y + z * z >= inside * inside) continue;
            const std::size_t node = grid.index(i, j, kz);
            // rigid rotation Omega z x r = (-Omega y, Omega x, 0)
            leak = std::max(leak, std::hypot(fluid.velocity(0)[node] + Omega * y, fluid.velocity(1)[node] - Omega * x,
                                             fluid.velocity(2)[node]));
          }
    }
    r.torque = T / torque_unit;
    r.stresslet = S / stresslet_unit;
    r.leakage = leak / (k * a);
    r.lag = lag / a;
    r.slip = slip / (k * a);
    r.slip_rms = std::sqrt(slip_rms) / (k * a);
    result.series.push_back(r);
  };

  const long steps = static_cast<long>(std::ceil(o.kt / k));
  const long every = std::max(1L, static_cast<long>(std::lround(o.every / k)));
  double* p[3] = {fluid.force(0), fluid.force(1), fluid.force(2)};
  const double* u[3] = {fluid.velocity(0), fluid.velocity(1), fluid.velocity(2)};
  for (long step = 0; step < steps; ++step) {
    const double phi = Omega * step, cs = std::cos(phi), sn = std::sin(phi);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = A0[3 * i] - c(0), y = A0[3 * i + 1] - c(1);
      A[3 * i] = c(0) + cs * x - sn * y;
      A[3 * i + 1] = c(1) + sn * x + cs * y;
      A[3 * i + 2] = A0[3 * i + 2];
    }
    for (std::size_t i = 0; i < 3 * n; ++i) F[i] = o.gain * (A[i] - X[i]);
    fluid.clear_force();
    ib::spread<3>(grid, X.data(), F.data(), n, p, kernel);  // (21)
    fluid.set_wall_velocity(-0.5 * k * H, 0.5 * k * H);    // (1)
    fluid.step();
    if (!std::isfinite(u[0][grid.index(nx / 2, ny / 2, nz / 2)]))
      throw std::runtime_error("rigid shell: the fluid blew up at kt = " + std::to_string(step * k));
    ib::interpolate<3>(grid, u, X.data(), n, U.data(), kernel);  // (19)
    if ((step + 1) % every == 0 || step + 1 == steps) row(step + 1);  // F, X, U: this step's force, where it acted
    ib::advance<3>(X.data(), U.data(), n, 1.0);                  // (20)
  }
  result.steps = steps;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void write_series_csv(const RigidShellResult& r, std::ostream& out) {
  out << "kt,torque,stresslet,leakage,lag,slip,slip_rms\n";
  out.precision(8);
  for (const auto& s : r.series)
    out << s.kt << "," << s.torque << "," << s.stresslet << "," << s.leakage << "," << s.lag << "," << s.slip << "," << s.slip_rms << "\n";
}

}  // namespace capsule::rigid_sphere
