#include "solver/membrane3d/surface_geometry.hpp"

#include <Eigen/Geometry>

namespace capsule::membrane3d {

Vec3 triangle_area_vector(const Mesh& m, int t) {
  const auto& tri = m.triangles[t];
  return (m.x[tri[1]] - m.x[tri[0]]).cross(m.x[tri[2]] - m.x[tri[0]]);
}

double surface_area(const Mesh& m) {
  double a = 0;
  for (int t = 0; t < m.triangle_count(); ++t) a += 0.5 * triangle_area_vector(m, t).norm();
  return a;
}

double enclosed_volume(const Mesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.x[t[0]].dot(m.x[t[1]].cross(m.x[t[2]]));
  return v / 6.0;
}

std::vector<Vec3> averaged_vertex_normals(const Mesh& m) {
  std::vector<Vec3> n;
  averaged_vertex_normals(m, n);
  return n;
}

void averaged_vertex_normals(const Mesh& m, std::vector<Vec3>& n) {
  const int nv = m.vertex_count();
  n.resize(nv);
  // Each vertex sums its own triangles in a fixed order: threads do not change the result.
#pragma omp parallel for schedule(static) if (nv > 2048)  // lighter per vertex than the fit: from level 4
  for (int v = 0; v < nv; ++v) {
    Vec3 s = Vec3::Zero();
    for (int t : m.vertex_triangles[v]) s += triangle_area_vector(m, t).normalized();
    n[v] = s.normalized();
  }
}

namespace {
// cot of the angle at corner a of triangle (a, b, c)
double cot_at(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, w = c - a;
  return u.dot(w) / u.cross(w).norm();
}
}  // namespace

std::vector<double> voronoi_areas(const Mesh& m) {
  std::vector<double> area;
  voronoi_areas(m, area);
  return area;
}

void voronoi_areas(const Mesh& m, std::vector<double>& area) {
  area.assign(m.vertex_count(), 0.0);
  for (const auto& t : m.triangles) {
    const Vec3 &p0 = m.x[t[0]], &p1 = m.x[t[1]], &p2 = m.x[t[2]];
    const double tri_area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    const double d0 = (p1 - p0).dot(p2 - p0), d1 = (p2 - p1).dot(p0 - p1), d2 = (p0 - p2).dot(p1 - p2);
    if (d0 < 0 || d1 < 0 || d2 < 0) {  // obtuse: mixed area
      area[t[0]] += tri_area * (d0 < 0 ? 0.5 : 0.25);
      area[t[1]] += tri_area * (d1 < 0 ? 0.5 : 0.25);
      area[t[2]] += tri_area * (d2 < 0 ? 0.5 : 0.25);
      continue;
    }
    // (83): each edge contributes cot(opposite angle) |edge|^2 / 8 to both its ends.
    const double c0 = cot_at(p0, p1, p2), c1 = cot_at(p1, p2, p0), c2 = cot_at(p2, p0, p1);
    const double e12 = (p2 - p1).squaredNorm(), e20 = (p0 - p2).squaredNorm(), e01 = (p1 - p0).squaredNorm();
    area[t[0]] += (c1 * e20 + c2 * e01) / 8.0;
    area[t[1]] += (c0 * e12 + c2 * e01) / 8.0;
    area[t[2]] += (c0 * e12 + c1 * e20) / 8.0;
  }
}

LaplaceBeltrami::LaplaceBeltrami(const Mesh& m) { update(m); }

void LaplaceBeltrami::update(const Mesh& m) {
  const int nv = m.vertex_count();
  if (offset_.size() != std::size_t(nv) + 1) {  // the topology: once per mesh
    offset_.assign(nv + 1, 0);
    for (int v = 0; v < nv; ++v) offset_[v + 1] = offset_[v] + m.ring[v].size();
    neighbour_.resize(offset_[nv]);
    for (int v = 0; v < nv; ++v) std::copy(m.ring[v].begin(), m.ring[v].end(), neighbour_.begin() + offset_[v]);
    weight_.resize(offset_[nv]);
  }
  voronoi_areas(m, area_);
  // Each vertex writes only its own weights: threads do not change the result.
#pragma omp parallel for schedule(static) if (nv > 2048)  // lighter per vertex than the fit: from level 4
  for (int v = 0; v < nv; ++v) {
    const auto& r = m.ring[v];
    const std::size_t n = r.size();
    for (std::size_t j = 0; j < n; ++j) {
      // Edge v-r[j]; the two triangles are (v, r[j-1], r[j]) and (v, r[j], r[j+1]).
      const Vec3& pj = m.x[r[j]];
      const Vec3& prev = m.x[r[(j + n - 1) % n]];
      const Vec3& next = m.x[r[(j + 1) % n]];
      weight_[offset_[v] + j] = 0.5 * (cot_at(prev, m.x[v], pj) + cot_at(next, m.x[v], pj));  // (82)
    }
  }
}

std::vector<double> LaplaceBeltrami::apply(const std::vector<double>& f) const {
  std::vector<double> out;
  apply(f, out);
  return out;
}

void LaplaceBeltrami::apply(const std::vector<double>& f, std::vector<double>& out) const {
  out.resize(f.size());
  for (std::size_t v = 0; v < f.size(); ++v) {
    double s = 0;
    for (std::size_t j = offset_[v]; j < offset_[v + 1]; ++j) s += weight_[j] * (f[neighbour_[j]] - f[v]);
    out[v] = s / area_[v];  // (81) with the standard sign
  }
}

}  // namespace capsule::membrane3d
