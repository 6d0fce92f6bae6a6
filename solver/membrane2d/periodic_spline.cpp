#include "solver/membrane2d/periodic_spline.hpp"

#include <cmath>
#include <stdexcept>

namespace capsule::membrane2d {

// off[i] couples unknowns i and i+1 (mod n): row i reads off[i-1] x[i-1] + diag[i] x[i] + off[i] x[i+1].
void solve_cyclic_tridiagonal_symmetric(const std::vector<double>& off, const std::vector<double>& diag,
                                        std::vector<double>& rx, std::vector<double>& ry,
                                        std::vector<double>& work, std::vector<double>& z) {
  const int n = static_cast<int>(diag.size());
  // Sherman-Morrison: A = T + u v^T with the corner entries alpha = A[n-1][0] = off[n-1],
  // beta = A[0][n-1] = off[n-1], gamma = -diag[0], u = (gamma, 0, .., alpha), v = (1, 0, .., beta/gamma).
  const double alpha = off[n - 1], beta = off[n - 1], gamma = -diag[0];
  work.resize(n);
  z.assign(n, 0.0);
  z[0] = gamma;
  z[n - 1] = alpha;
  // Thomas elimination of T (diagonal modified at both ends), applied to rx, ry and z at once.
  auto d = [&](int i) {
    if (i == 0) return diag[0] - gamma;
    if (i == n - 1) return diag[n - 1] - alpha * beta / gamma;
    return diag[i];
  };
  double inv = 1.0 / d(0);
  work[0] = off[0] * inv;
  rx[0] *= inv;
  ry[0] *= inv;
  z[0] *= inv;
  for (int i = 1; i < n; ++i) {
    const double sub = off[i - 1];
    inv = 1.0 / (d(i) - sub * work[i - 1]);
    work[i] = i < n - 1 ? off[i] * inv : 0.0;
    rx[i] = (rx[i] - sub * rx[i - 1]) * inv;
    ry[i] = (ry[i] - sub * ry[i - 1]) * inv;
    z[i] = (z[i] - sub * z[i - 1]) * inv;
  }
  for (int i = n - 2; i >= 0; --i) {
    rx[i] -= work[i] * rx[i + 1];
    ry[i] -= work[i] * ry[i + 1];
    z[i] -= work[i] * z[i + 1];
  }
  const double vz = 1.0 + z[0] + beta * z[n - 1] / gamma;
  const double fx = (rx[0] + beta * rx[n - 1] / gamma) / vz;
  const double fy = (ry[0] + beta * ry[n - 1] / gamma) / vz;
  for (int i = 0; i < n; ++i) {
    rx[i] -= fx * z[i];
    ry[i] -= fy * z[i];
  }
}

void PeriodicSpline::fit(const std::vector<double>& xy) {
  const int n = static_cast<int>(xy.size() / 2);
  if (n < 4) throw std::invalid_argument("PeriodicSpline: need at least 4 nodes");
  if (n != n_) {
    n_ = n;
    h_.assign(n, 0.0);
    diag_.assign(n, 0.0);
    Mx_.assign(n, 0.0);
    My_.assign(n, 0.0);
    kappa_.assign(n, 0.0);
    tx_.assign(n, 0.0);
    ty_.assign(n, 0.0);
  }
  // chord vectors e_i = P_{i+1} - P_i, their lengths h_i (the chord-length parameter) and slopes
  ex_.resize(n);
  ey_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int ip = i + 1 < n ? i + 1 : 0;
    const double dx = xy[2 * ip] - xy[2 * i], dy = xy[2 * ip + 1] - xy[2 * i + 1];
    h_[i] = std::sqrt(dx * dx + dy * dy);
    ex_[i] = dx / h_[i];
    ey_[i] = dy / h_[i];
  }
  // Second derivatives M_i at the knots: h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
  //   = 6 [(P_{i+1} - P_i)/h_i - (P_i - P_{i-1})/h_{i-1}], cyclic.
  for (int i = 0; i < n; ++i) {
    const int im = i > 0 ? i - 1 : n - 1;
    diag_[i] = 2.0 * (h_[im] + h_[i]);
    Mx_[i] = 6.0 * (ex_[i] - ex_[im]);
    My_[i] = 6.0 * (ey_[i] - ey_[im]);
  }
  solve_cyclic_tridiagonal_symmetric(h_, diag_, Mx_, My_, work_, z_);
  for (int i = 0; i < n; ++i) {
    const int ip = i + 1 < n ? i + 1 : 0;
    // first derivative at the left end of interval i
    const double dx = ex_[i] - h_[i] * (2.0 * Mx_[i] + Mx_[ip]) / 6.0;
    const double dy = ey_[i] - h_[i] * (2.0 * My_[i] + My_[ip]) / 6.0;
    const double speed2 = dx * dx + dy * dy, speed = std::sqrt(speed2);
    kappa_[i] = (dx * My_[i] - dy * Mx_[i]) / (speed2 * speed);
    tx_[i] = dx / speed;
    ty_[i] = dy / speed;
  }
}

}  // namespace capsule::membrane2d
