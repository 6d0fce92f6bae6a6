#include "solver/membrane3d/curvature.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "solver/membrane3d/surface_geometry.hpp"

namespace capsule::membrane3d {

namespace {

struct Fit {
  double mean, gaussian;
  Vec3 normal;
};

Fit fit_vertex(const Mesh& m, int p, const Vec3& n) {
  // (73)-(75): rows r1, r2, r3 = n of the rotation into the local frame.
  Vec3 axis = Vec3::UnitX();
  Vec3 r1 = axis - n * n.dot(axis);
  if (r1.norm() < 1e-3) {  // normal (anti)parallel to x: (73) is undefined, use y instead
    axis = Vec3::UnitY();
    r1 = axis - n * n.dot(axis);
  }
  r1.normalize();
  const Vec3 r2 = n.cross(r1);
  Eigen::Matrix3d R;
  R.row(0) = r1.transpose();
  R.row(1) = r2.transpose();
  R.row(2) = n.transpose();

  const auto& ring = m.ring[p];
  const int k = static_cast<int>(ring.size());
  // Local coordinates (76) scaled by the mean ring distance h, so that the columns of (77)
  // are O(1) and the least-squares normal equations are well conditioned:
  // z/h = a' (x/h)^2 + ... gives a = a'/h, b = b'/h, c = c'/h, d = d', e = e'.
  double h = 0;
  for (int j = 0; j < k; ++j) h += (m.x[ring[j]] - m.x[p]).norm();
  h /= k;
  Eigen::Matrix<double, 5, 5> AtA = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> Atz = Eigen::Matrix<double, 5, 1>::Zero();
  for (int j = 0; j < k; ++j) {
    const Vec3 q = R * (m.x[ring[j]] - m.x[p]) / h;  // (76)
    Eigen::Matrix<double, 5, 1> row;
    row << q.x() * q.x(), q.x() * q.y(), q.y() * q.y(), q.x(), q.y();  // one row of (77)
    AtA.noalias() += row * row.transpose();
    Atz += row * q.z();
  }
  // 5 neighbours: the square system (77) solved exactly; 6 or more: its least-squares
  // solution. Both are the solution of the normal equations, symmetric positive definite for
  // a ring that is not degenerate: Cholesky (Eigen LL^T, about half the time of LDL^T with its
  // pivoting; the curvatures agree to round-off).
  Eigen::Matrix<double, 5, 1> s = AtA.llt().solve(Atz);
  s.head<3>() /= h;
  const double a = s(0), b = s(1), c = s(2), d = s(3), e = s(4);
  const double g = 1.0 + d * d + e * e;
  Fit f;
  f.gaussian = (4.0 * a * c - b * b) / (g * g);                                // (78)
  f.mean = -(a * (1.0 + e * e) + c * (1.0 + d * d) - b * d * e) / (g * std::sqrt(g));  // (79), corrected
  f.normal = (R.transpose() * Vec3(-d, -e, 1.0)).normalized();                  // (80)
  return f;
}

}  // namespace

Curvatures fit_curvatures(const Mesh& m, int passes) {
  Curvatures out;
  fit_curvatures(m, out, passes);
  return out;
}

void fit_curvatures(const Mesh& m, Curvatures& out, int passes) {
  const int nv = m.vertex_count();
  out.mean.resize(nv);
  out.gaussian.resize(nv);
  averaged_vertex_normals(m, out.normal, out.triangle_normal);
  for (int pass = 0; pass < passes; ++pass) {
    // Each vertex's fit reads and writes only its own normal: threads do not change the result.
    // Level 4, 2 threads, idle machine: the curvature share of a step 2.0-2.1 -> 1.6-1.8 ms.
#pragma omp parallel for schedule(static) if (nv > 512)
    for (int p = 0; p < nv; ++p) {
      const Fit f = fit_vertex(m, p, out.normal[p]);
      out.mean[p] = f.mean;
      out.gaussian[p] = f.gaussian;
      out.normal[p] = f.normal;
    }
  }
}

}  // namespace capsule::membrane3d
