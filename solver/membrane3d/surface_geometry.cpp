#include "solver/membrane3d/surface_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>

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
  std::vector<Vec3> triangle_normal;
  averaged_vertex_normals(m, n, triangle_normal);
}

void averaged_vertex_normals(const Mesh& m, std::vector<Vec3>& n, std::vector<Vec3>& triangle_normal) {
  const int nv = m.vertex_count(), nt = m.triangle_count();
  n.resize(nv);
  triangle_normal.resize(nt);
  // Each triangle's unit normal once (not once for each of its three vertices), then each vertex
  // sums its own triangles' in a fixed order: threads do not change the result.
#pragma omp parallel if (nv > 2048)  // lighter per vertex than the fit: from level 4
  {
#pragma omp for schedule(static)
    for (int t = 0; t < nt; ++t) triangle_normal[t] = triangle_area_vector(m, t).normalized();
#pragma omp for schedule(static)
    for (int v = 0; v < nv; ++v) {
      Vec3 s = Vec3::Zero();
      for (int t : m.vertex_triangles[v]) s += triangle_normal[t];
      n[v] = s.normalized();
    }
  }
}

namespace {
// cot of the angle at corner a of triangle (a, b, c); cot_at(a, c, b) gives the same bits (the
// products commute, the cross product only changes sign).
double cot_at(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, w = c - a;
  return u.dot(w) / u.cross(w).norm();
}

// Triangle t's share of the Voronoi area (83) of each of its corners, share[c], and the
// cotangent of its angle at each corner, cot[c] = cot_at(x_c, x_c+1, x_c+2) (the weights (82)).
void triangle_corners(const Mesh& m, int t, double* share, double* cot) {
  const Triangle& tri = m.triangles[t];
  const Vec3 &p0 = m.x[tri[0]], &p1 = m.x[tri[1]], &p2 = m.x[tri[2]];
  cot[0] = cot_at(p0, p1, p2), cot[1] = cot_at(p1, p2, p0), cot[2] = cot_at(p2, p0, p1);
  const double d0 = (p1 - p0).dot(p2 - p0), d1 = (p2 - p1).dot(p0 - p1), d2 = (p0 - p2).dot(p1 - p2);
  if (d0 < 0 || d1 < 0 || d2 < 0) {  // obtuse: mixed area
    const double tri_area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    share[0] = tri_area * (d0 < 0 ? 0.5 : 0.25);
    share[1] = tri_area * (d1 < 0 ? 0.5 : 0.25);
    share[2] = tri_area * (d2 < 0 ? 0.5 : 0.25);
    return;
  }
  // (83): each edge contributes cot(opposite angle) |edge|^2 / 8 to both its ends.
  const double e12 = (p2 - p1).squaredNorm(), e20 = (p0 - p2).squaredNorm(), e01 = (p1 - p0).squaredNorm();
  share[0] = (cot[1] * e20 + cot[2] * e01) / 8.0;
  share[1] = (cot[0] * e12 + cot[2] * e01) / 8.0;
  share[2] = (cot[0] * e12 + cot[1] * e20) / 8.0;
}

// a_vor(v) = the shares of v's triangles summed in the order of vertex_triangles[v] (increasing
// triangle index: the order in which voronoi_areas' loop over the triangles adds them).
double gathered_area(const Mesh& m, int v, const std::vector<double>& share) {
  double a = 0.0;
  for (std::size_t n = 0; n < m.vertex_triangles[v].size(); ++n)
    a += share[3 * m.vertex_triangles[v][n] + m.corner_in_triangle[v][n]];
  return a;
}
}  // namespace

std::vector<double> voronoi_areas(const Mesh& m) {
  std::vector<double> area;
  voronoi_areas(m, area);
  return area;
}

void voronoi_areas(const Mesh& m, std::vector<double>& area) {
  area.assign(m.vertex_count(), 0.0);
  for (int t = 0; t < m.triangle_count(); ++t) {
    double share[3], cot[3];
    triangle_corners(m, t, share, cot);
    for (int c = 0; c < 3; ++c) area[m.triangles[t][c]] += share[c];
  }
}

LaplaceBeltrami::LaplaceBeltrami(const Mesh& m) { update(m); }

void LaplaceBeltrami::update(const Mesh& m) {
  const int nv = m.vertex_count(), nt = m.triangle_count();
  if (offset_.size() != std::size_t(nv) + 1) {  // the topology: once per mesh
    offset_.assign(nv + 1, 0);
    for (int v = 0; v < nv; ++v) offset_[v + 1] = offset_[v] + m.ring[v].size();
    neighbour_.resize(offset_[nv]);
    for (int v = 0; v < nv; ++v) std::copy(m.ring[v].begin(), m.ring[v].end(), neighbour_.begin() + offset_[v]);
    weight_.resize(offset_[nv]);
    // Edge v-r[j] has the triangles (v, r[j-1], r[j]) and (v, r[j], r[j+1]); its weight (82) takes
    // the cotangents at r[j-1] and at r[j+1]. In v's triangle (v, a, b) b follows a in the ring:
    // the angle at a belongs to edge v-b, the angle at b to edge v-a.
    angle_before_.resize(offset_[nv]);
    angle_after_.resize(offset_[nv]);
    for (int v = 0; v < nv; ++v) {
      const auto& r = m.ring[v];
      auto position = [&](int u) { return offset_[v] + (std::find(r.begin(), r.end(), u) - r.begin()); };
      for (std::size_t n = 0; n < m.vertex_triangles[v].size(); ++n) {
        const int t = m.vertex_triangles[v][n], c = m.corner_in_triangle[v][n];
        const Triangle& tri = m.triangles[t];
        angle_before_[position(tri[(c + 2) % 3])] = 3 * t + (c + 1) % 3;
        angle_after_[position(tri[(c + 1) % 3])] = 3 * t + (c + 2) % 3;
      }
    }
    share_.resize(3 * nt);
    cot_.resize(3 * nt);
  }
  area_.resize(nv);
  // Each triangle's cotangents and area shares once (not once for each of its vertices), then
  // each vertex gathers its own area and weights: threads do not change the result.
#pragma omp parallel if (nv > 2048)  // lighter per vertex than the fit: from level 4
  {
#pragma omp for schedule(static)
    for (int t = 0; t < nt; ++t) triangle_corners(m, t, &share_[3 * t], &cot_[3 * t]);
#pragma omp for schedule(static)
    for (int v = 0; v < nv; ++v) {
      area_[v] = gathered_area(m, v, share_);
      for (std::size_t j = offset_[v]; j < offset_[v + 1]; ++j)
        weight_[j] = 0.5 * (cot_[angle_before_[j]] + cot_[angle_after_[j]]);  // (82)
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
