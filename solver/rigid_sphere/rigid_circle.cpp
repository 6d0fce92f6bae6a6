#include "solver/rigid_sphere/rigid_circle.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "solver/ib/delta.hpp"
#include "solver/ib/grid.hpp"
#include "solver/ib/interpolation.hpp"
#include "solver/lbm/fluid.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/precision.hpp"

namespace capsule::rigid_sphere {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("rigid circle: " + what);
}

}  // namespace

void validate(const RigidCircleOptions& o) {
  require(o.a >= 2 && o.a <= 200, "a must be in [2, 200] lattice units, got " + std::to_string(o.a));
  const double r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  require(r_m >= 0.5 * o.a && r_m <= 1.5 * o.a, "marker_radius must be in [a/2, 3a/2], got " + std::to_string(o.marker_radius));
  require(o.segments >= 16 && o.segments <= 100000, "segments must be in [16, 100000], got " + std::to_string(o.segments));
  for (double d : o.domain) require(d >= 3 && d <= 100, "each domain side must be in [3, 100] a, got " + std::to_string(d));
  require(o.Re > 0 && o.Re <= 1, "Re must be in (0, 1], got " + std::to_string(o.Re));
  require(o.tau > 0.5 && o.tau <= 5, "tau must be in (0.5, 5], got " + std::to_string(o.tau));
  require(std::abs(o.spin) <= 2, "spin must be in [-2, 2] (units of k), got " + std::to_string(o.spin));
  require(o.kt > 0 && o.kt <= 100, "kt must be in (0, 100], got " + std::to_string(o.kt));
  require(o.gain > 0 && o.gain <= 1, "gain must be in (0, 1], got " + std::to_string(o.gain));
  require(o.every > 0 && o.every <= o.kt, "every must be in (0, kt], got " + std::to_string(o.every));
  ib::kernel_from_name(o.kernel);
  lbm::precision_from_name(o.precision);
}

RigidShellResult run_rigid_circle(const RigidCircleOptions& o) {
  validate(o);
  const auto start = std::chrono::steady_clock::now();
  const double a = o.a, r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  const double nu = (o.tau - 0.5) / 3.0, mu = nu;  // (8), rho = 1
  const double k = o.Re * nu / (a * a);
  const double Omega = o.spin * k;
  RigidShellResult result;
  result.grid[0] = static_cast<int>(std::lround(o.domain[0] * a));
  result.grid[1] = static_cast<int>(std::lround(o.domain[1] * a));
  result.grid[2] = 1;
  const int nx = result.grid[0], ny = result.grid[1];
  const ib::Grid grid{nx, ny, 1};
  const ib::Kernel kernel = ib::kernel_from_name(o.kernel);
  lbm::Fluid<lbm::D2Q9> fluid(nx, ny, 1, nu, lbm::precision_from_name(o.precision));
  const double H = ny;
  fluid.initialise_velocity([&](double, double y, double) { return std::array<double, 3>{k * (y - 0.5 * H), 0.0, 0.0}; });

  const double cx = 0.5 * nx, cy = 0.5 * ny;
  const std::size_t n = static_cast<std::size_t>(o.segments);
  std::vector<double> A0(2 * n), X(2 * n), F(2 * n), U(2 * n), A(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    // Offset by half a segment from the axes, as the 2D capsule's nodes inclined 45 degrees are not aligned either.
    const double phi = 2.0 * std::numbers::pi * (i + 0.5) / n;
    A0[2 * i] = X[2 * i] = cx + r_m * std::cos(phi);
    A0[2 * i + 1] = X[2 * i + 1] = cy + r_m * std::sin(phi);
  }

  // Unbounded values per unit length: torque 2 pi mu a^2 k (1 + 2 spin), stresslet 2 pi mu a^2 k.
  const double unit = 2.0 * std::numbers::pi * mu * a * a * k;
  result.torque_exact = 1.0 + 2.0 * o.spin;
  const double inside = r_m - 2.5;  // nodes deeper than the kernel's reach (2) plus half a node

  auto row = [&](long step) {
    RigidShellRow r;
    r.kt = step * k;
    double T = 0, S = 0, lag = 0, slip = 0, slip_rms = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = X[2 * i] - cx, y = X[2 * i + 1] - cy;
      const double s2 = std::pow(U[2 * i] + Omega * y, 2) + std::pow(U[2 * i + 1] - Omega * x, 2);
      slip = std::max(slip, std::sqrt(s2));
      slip_rms += s2 / n;
      T += x * F[2 * i + 1] - y * F[2 * i];
      S -= 0.5 * (x * F[2 * i + 1] + y * F[2 * i]);
      lag = std::max(lag, std::hypot(A[2 * i] - X[2 * i], A[2 * i + 1] - X[2 * i + 1]));
    }
    double leak = 0;
    if (inside > 0) {
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const double x = i + 0.5 - cx, y = j + 0.5 - cy;
          if (x * x + y * y >= inside * inside) continue;
          const std::size_t node = grid.index(i, j, 0);
          leak = std::max(leak, std::hypot(fluid.velocity(0)[node] + Omega * y, fluid.velocity(1)[node] - Omega * x));
        }
    }
    r.torque = T / unit;
    r.stresslet = S / unit;
    r.leakage = leak / (k * a);
    r.lag = lag / a;
    r.slip = slip / (k * a);
    r.slip_rms = std::sqrt(slip_rms) / (k * a);
    result.series.push_back(r);
  };

  const long steps = static_cast<long>(std::ceil(o.kt / k));
  const long every = std::max(1L, static_cast<long>(std::lround(o.every / k)));
  double* p[2] = {fluid.force(0), fluid.force(1)};
  const double* u[2] = {fluid.velocity(0), fluid.velocity(1)};
  for (long step = 0; step < steps; ++step) {
    const double phi = Omega * step, cs = std::cos(phi), sn = std::sin(phi);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = A0[2 * i] - cx, y = A0[2 * i + 1] - cy;
      A[2 * i] = cx + cs * x - sn * y;
      A[2 * i + 1] = cy + sn * x + cs * y;
    }
    for (std::size_t i = 0; i < 2 * n; ++i) F[i] = o.gain * (A[i] - X[i]);
    fluid.clear_force();
    ib::spread<2>(grid, X.data(), F.data(), n, p, kernel);  // (21)
    fluid.set_wall_velocity(-0.5 * k * H, 0.5 * k * H);   // (1)
    fluid.step();
    if (!std::isfinite(u[0][grid.index(nx / 2, ny / 2, 0)]))
      throw std::runtime_error("rigid circle: the fluid blew up at kt = " + std::to_string(step * k));
    ib::interpolate<2>(grid, u, X.data(), n, U.data(), kernel);  // (19)
    if ((step + 1) % every == 0 || step + 1 == steps) row(step + 1);
    ib::advance<2>(X.data(), U.data(), n, 1.0);  // (20)
  }
  result.steps = steps;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace capsule::rigid_sphere
