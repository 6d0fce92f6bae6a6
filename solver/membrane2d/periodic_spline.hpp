#pragma once
// Periodic parametric cubic spline through the closed membrane polygon (Sec. 2.4, docs/guide/model.md "The 2D capsule"):
// x(s) and y(s) with s the cumulative chord length, C2 and periodic. At every node it gives
// the unit tangent and the curvature kappa = (x' y'' - y' x'') / (x'^2 + y'^2)^(3/2)
// (the parametric form of (33), whose F''' should read F''). Counter-clockwise nodes give
// kappa > 0 on a convex shape (a circle of radius a: 1/a).
// The knot second derivatives solve a cyclic tridiagonal system, strictly diagonally dominant,
// by the Thomas algorithm with a Sherman-Morrison correction for the corners: O(n), ~1 us for
// 140 nodes (Eigen's sparse LDLT took 33 us, most of a membrane step; Eigen has no banded solver).
#include <vector>

namespace capsule::membrane2d {

class PeriodicSpline {
 public:
  // xy: n nodes, flat (x0, y0, x1, y1, ...). Refits everything (O(n)).
  void fit(const std::vector<double>& xy);

  int size() const { return n_; }
  double curvature(int i) const { return kappa_[i]; }
  const std::vector<double>& curvatures() const { return kappa_; }
  double tangent_x(int i) const { return tx_[i]; }  // unit tangent at node i
  double tangent_y(int i) const { return ty_[i]; }

 private:
  int n_ = 0;
  std::vector<double> h_, ex_, ey_, diag_, Mx_, My_, work_, z_;
  std::vector<double> kappa_, tx_, ty_;
};

// Solves the cyclic tridiagonal system sub[i] x[i-1] + diag[i] x[i] + sup[i] x[i+1] = r[i]
// (indices mod n) for two right-hand sides in place (rx, ry); symmetric here: sub[i] = sup[i-1].
// Needs diagonal dominance (no pivoting). work, z: scratch of size n.
void solve_cyclic_tridiagonal_symmetric(const std::vector<double>& off, const std::vector<double>& diag,
                                        std::vector<double>& rx, std::vector<double>& ry,
                                        std::vector<double>& work, std::vector<double>& z);

}  // namespace capsule::membrane2d
