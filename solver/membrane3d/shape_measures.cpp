#include "solver/membrane3d/shape_measures.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace capsule::membrane3d {

namespace {
Vec3 vertex_mean(const Mesh& m) {
  Vec3 c = Vec3::Zero();
  for (const auto& p : m.x) c += p;
  return c / static_cast<double>(m.x.size());
}
}  // namespace

Vec3 volume_centroid(const Mesh& m) {
  const Vec3 o = vertex_mean(m);  // origin of the tetrahedra, for round-off
  double vol = 0;
  Vec3 first = Vec3::Zero();
  for (const auto& t : m.triangles) {
    const Vec3 a = m.x[t[0]] - o, b = m.x[t[1]] - o, c = m.x[t[2]] - o;
    const double v = a.dot(b.cross(c)) / 6.0;
    vol += v;
    first += v * (a + b + c) / 4.0;
  }
  return o + first / vol;
}

InertiaDeformation inertia_deformation(const Mesh& m) {
  InertiaDeformation out;
  out.centroid = volume_centroid(m);
  const Vec3 o = out.centroid;
  double vol = 0;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();  // int r r^T dV about the centroid
  for (const auto& t : m.triangles) {
    const Vec3 a = m.x[t[0]] - o, b = m.x[t[1]] - o, c = m.x[t[2]] - o;
    const double v = a.dot(b.cross(c)) / 6.0;
    const Vec3 s = a + b + c;
    vol += v;
    M += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  const Eigen::Matrix2d Mxy = M.topLeftCorner<2, 2>();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(Mxy);
  const double mu_min = std::max(eig.eigenvalues()(0), 0.0), mu_max = std::max(eig.eigenvalues()(1), 0.0);
  out.L = 2.0 * std::sqrt(5.0 * mu_max / vol);
  out.W = 2.0 * std::sqrt(5.0 * mu_min / vol);
  out.D = (out.L - out.W) / (out.L + out.W);
  out.theta = 0.5 * std::atan2(2.0 * Mxy(0, 1), Mxy(0, 0) - Mxy(1, 1));
  return out;
}

double extent_deformation(const Mesh& m, const Vec3& centre) {
  const double zc = centre.z();
  double r_max = 0, r_min = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d c(centre.x(), centre.y());
  for (const auto& t : m.triangles) {
    Eigen::Vector2d pts[3];
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const Vec3 &p = m.x[t[e]], &q = m.x[t[(e + 1) % 3]];
      if ((p.z() >= zc) == (q.z() >= zc)) continue;
      const double s = (zc - p.z()) / (q.z() - p.z());
      const Vec3 x = p + s * (q - p);
      pts[n++] = Eigen::Vector2d(x.x(), x.y());
    }
    if (n != 2) continue;
    const Eigen::Vector2d d = pts[1] - pts[0];
    r_max = std::max({r_max, (pts[0] - c).norm(), (pts[1] - c).norm()});
    const double s = std::clamp((c - pts[0]).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    r_min = std::min(r_min, (pts[0] + s * d - c).norm());
  }
  if (!(r_max > 0) || !std::isfinite(r_min)) return std::numeric_limits<double>::quiet_NaN();
  return (r_max - r_min) / (r_max + r_min);
}

double min_triangle_quality(const Mesh& m) {
  double q = 1.0;
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.x[t[0]], &b = m.x[t[1]], &c = m.x[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    q = std::min(q, 4.0 * std::sqrt(3.0) * area / l2);
  }
  return q;
}

}  // namespace capsule::membrane3d
