#include "solver/membrane3d/optical_tweezers.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "solver/membrane3d/surface_geometry.hpp"

namespace capsule::membrane3d {
namespace {

// The poles: where the x axis through the vertices' centroid meets the membrane's extreme x.
std::pair<Vec3, Vec3> poles(const Mesh& m) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : m.x) c += p;
  c /= static_cast<double>(m.vertex_count());
  double hi = -INFINITY, lo = INFINITY;
  for (const Vec3& p : m.x) hi = std::max(hi, p.x()), lo = std::min(lo, p.x());
  return {Vec3(hi, c.y(), c.z()), Vec3(lo, c.y(), c.z())};
}

// The vertices within `radius` of `pole` (a relative slack of 1e-9 keeps symmetric ties
// together) and their area shares.
void fill_patch(const Mesh& m, const std::vector<double>& areas, const Vec3& pole, double radius,
                std::vector<int>& vertices, std::vector<double>& shares, double& area) {
  const double limit = radius * (1.0 + 1e-9);
  area = 0;
  for (int v = 0; v < m.vertex_count(); ++v)
    if ((m.x[v] - pole).norm() <= limit) {
      vertices.push_back(v);
      area += areas[v];
    }
  for (int v : vertices) shares.push_back(areas[v] / area);
}

// The distance from `pole` of its n-th nearest vertex (n >= 1).
double nth_distance(const Mesh& m, const Vec3& pole, int n) {
  std::vector<double> d(m.vertex_count());
  for (int v = 0; v < m.vertex_count(); ++v) d[v] = (m.x[v] - pole).norm();
  std::nth_element(d.begin(), d.begin() + (n - 1), d.end());
  return d[n - 1];
}

PulledPatches patches_within(const Mesh& m, double plus_radius, double minus_radius) {
  const auto [plus_pole, minus_pole] = poles(m);
  const std::vector<double> areas = voronoi_areas(m);
  PulledPatches p;
  fill_patch(m, areas, plus_pole, plus_radius, p.plus, p.plus_share, p.plus_area);
  fill_patch(m, areas, minus_pole, minus_radius, p.minus, p.minus_share, p.minus_area);
  return p;
}

}  // namespace

PulledPatches patches_by_fraction(const Mesh& m, double fraction) {
  if (!(fraction > 0 && fraction < 0.5)) throw std::invalid_argument("patch fraction outside (0, 0.5)");
  const int n = std::max(1, static_cast<int>(std::lround(fraction * m.vertex_count())));
  const auto [plus_pole, minus_pole] = poles(m);
  return patches_within(m, nth_distance(m, plus_pole, n), nth_distance(m, minus_pole, n));
}

PulledPatches patches_by_contact_diameter(const Mesh& m, double contact_diameter) {
  if (!(contact_diameter > 0)) throw std::invalid_argument("contact diameter must be positive");
  const auto [plus_pole, minus_pole] = poles(m);
  const double r = 0.5 * contact_diameter;
  return patches_within(m, std::max(r, nth_distance(m, plus_pole, 1)), std::max(r, nth_distance(m, minus_pole, 1)));
}

void add_pulling_forces(const PulledPatches& p, double F, std::vector<Vec3>& force) {
  for (std::size_t i = 0; i < p.plus.size(); ++i) force[p.plus[i]].x() += F * p.plus_share[i];
  for (std::size_t i = 0; i < p.minus.size(); ++i) force[p.minus[i]].x() -= F * p.minus_share[i];
}

StretchDiameters stretch_diameters(const Mesh& m) {
  StretchDiameters d;
  double hi = -INFINITY, lo = INFINITY;
  for (const Vec3& p : m.x) hi = std::max(hi, p.x()), lo = std::min(lo, p.x());
  d.axial = hi - lo;
  // The projection's diameter is that of its convex hull (Andrew's monotone chain), whose few
  // vertices are then compared pairwise.
  std::vector<std::pair<double, double>> q(m.vertex_count());
  for (int v = 0; v < m.vertex_count(); ++v) q[v] = {m.x[v].y(), m.x[v].z()};
  std::sort(q.begin(), q.end());
  q.erase(std::unique(q.begin(), q.end()), q.end());
  const auto cross = [](const auto& o, const auto& a, const auto& b) {
    return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
  };
  std::vector<std::pair<double, double>> hull(2 * q.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], q[i]) <= 0) --k;
    hull[k++] = q[i];
  }
  for (std::size_t i = q.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], q[i]) <= 0) --k;
    hull[k++] = q[i];
  }
  hull.resize(q.size() > 1 ? k - 1 : q.size());
  double widest = 0;
  for (std::size_t i = 0; i < hull.size(); ++i)
    for (std::size_t j = i + 1; j < hull.size(); ++j)
      widest = std::max(widest, std::hypot(hull[i].first - hull[j].first, hull[i].second - hull[j].second));
  d.transverse = widest;
  return d;
}

}  // namespace capsule::membrane3d
