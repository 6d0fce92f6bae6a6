// The per-vertex surface geometry gathered from per-triangle parts (surface_geometry.cpp: each
// triangle's normal, cotangents and Voronoi shares computed once) gives bitwise what the
// per-vertex formulas gave, on any thread count: the member's physics does not change.
#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <random>
#include <vector>

#include "solver/membrane3d/curvature.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "solver/membrane3d/surface_geometry.hpp"

using namespace capsule::membrane3d;

namespace {

// The formulas as they were written per vertex (the code before the per-triangle parts).
double cot_at(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, w = c - a;
  return u.dot(w) / u.cross(w).norm();
}

std::vector<Vec3> direct_normals(const Mesh& m) {
  std::vector<Vec3> n(m.vertex_count());
  for (int v = 0; v < m.vertex_count(); ++v) {
    Vec3 s = Vec3::Zero();
    for (int t : m.vertex_triangles[v]) s += triangle_area_vector(m, t).normalized();
    n[v] = s.normalized();
  }
  return n;
}

std::vector<double> direct_voronoi(const Mesh& m) {
  std::vector<double> area(m.vertex_count(), 0.0);
  for (const auto& t : m.triangles) {
    const Vec3 &p0 = m.x[t[0]], &p1 = m.x[t[1]], &p2 = m.x[t[2]];
    const double tri_area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    const double d0 = (p1 - p0).dot(p2 - p0), d1 = (p2 - p1).dot(p0 - p1), d2 = (p0 - p2).dot(p1 - p2);
    if (d0 < 0 || d1 < 0 || d2 < 0) {
      area[t[0]] += tri_area * (d0 < 0 ? 0.5 : 0.25);
      area[t[1]] += tri_area * (d1 < 0 ? 0.5 : 0.25);
      area[t[2]] += tri_area * (d2 < 0 ? 0.5 : 0.25);
      continue;
    }
    const double c0 = cot_at(p0, p1, p2), c1 = cot_at(p1, p2, p0), c2 = cot_at(p2, p0, p1);
    const double e12 = (p2 - p1).squaredNorm(), e20 = (p0 - p2).squaredNorm(), e01 = (p1 - p0).squaredNorm();
    area[t[0]] += (c1 * e20 + c2 * e01) / 8.0;
    area[t[1]] += (c0 * e12 + c2 * e01) / 8.0;
    area[t[2]] += (c0 * e12 + c1 * e20) / 8.0;
  }
  return area;
}

// (81) with the weights (82) computed per vertex and ring neighbour.
std::vector<double> direct_laplacian(const Mesh& m, const std::vector<double>& f) {
  const std::vector<double> area = direct_voronoi(m);
  std::vector<double> out(f.size());
  for (int v = 0; v < m.vertex_count(); ++v) {
    const auto& r = m.ring[v];
    const std::size_t n = r.size();
    double s = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const Vec3& pj = m.x[r[j]];
      const double w = 0.5 * (cot_at(m.x[r[(j + n - 1) % n]], m.x[v], pj) + cot_at(m.x[r[(j + 1) % n]], m.x[v], pj));
      s += w * (f[r[j]] - f[v]);
    }
    out[v] = s / area[v];
  }
  return out;
}

}  // namespace

TEST_CASE("normals, Voronoi areas and Laplace-Beltrami gathered per triangle are bitwise the per-vertex formulas",
          "[membrane3d]") {
  // A level-4 sphere (2562 vertices: the threaded loops run threaded), stretched and shaken so
  // that the triangles differ and some are obtuse (the mixed areas).
  Mesh m = sphere_mesh(unit_icosphere(4), 10.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> shake(-0.2, 0.2);
  for (auto& x : m.x) x = Vec3(1.6 * x.x(), x.y() / 1.3, x.z()) + Vec3(shake(rng), shake(rng), shake(rng));
  int obtuse = 0;
  for (const auto& t : m.triangles) {
    const Vec3 &p0 = m.x[t[0]], &p1 = m.x[t[1]], &p2 = m.x[t[2]];
    obtuse += (p1 - p0).dot(p2 - p0) < 0 || (p2 - p1).dot(p0 - p1) < 0 || (p0 - p2).dot(p1 - p2) < 0;
  }
  REQUIRE(obtuse > 10);
  std::vector<double> f(m.vertex_count());
  for (int v = 0; v < m.vertex_count(); ++v) f[v] = std::sin(m.x[v].x()) * m.x[v].z();
  const std::vector<Vec3> normals = direct_normals(m);
  const std::vector<double> areas = direct_voronoi(m), laplacian = direct_laplacian(m, f);
  for (int threads : {1, 2, 3}) {
    INFO(threads << " threads");
    omp_set_num_threads(threads);
    REQUIRE(averaged_vertex_normals(m) == normals);
    REQUIRE(fit_curvatures(m).triangle_normal.size() == m.triangles.size());
    REQUIRE(voronoi_areas(m) == areas);
    LaplaceBeltrami lb(m);
    REQUIRE(lb.areas() == areas);
    REQUIRE(lb.apply(f) == laplacian);
    lb.update(m);  // again, reusing the topology
    REQUIRE(lb.apply(f) == laplacian);
  }
  omp_set_num_threads(1);
}
