#include "solver/membrane3d/slices.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/membrane3d/shape_measures.hpp"

namespace capsule::membrane3d {

namespace {

using Key = std::pair<int, int>;  // undirected mesh edge (i < j) crossed by the plane

Key edge_key(int i, int j) { return i < j ? Key{i, j} : Key{j, i}; }

// Section of the mapped positions q by the plane q[axis] = 0; points (q[u], q[v]) / scale.
std::vector<Polyline> section(const std::vector<Vec3>& q, const std::vector<Triangle>& triangles, int axis, int u,
                              int v, double scale, double eps) {
  // Crossing point of an edge, computed once per undirected edge so that both triangles
  // sharing it see the identical point. A vertex exactly on the plane (d = 0, counted as
  // positive) is itself the crossing point.
  std::map<Key, std::array<double, 2>> crossing;
  auto point_of = [&](const Key& k) {
    auto [it, inserted] = crossing.try_emplace(k);
    if (inserted) {
      const Vec3& a = q[k.first];
      const Vec3& b = q[k.second];
      const double da = a[axis], db = b[axis];
      Vec3 p;
      if (da == 0.0) p = a;
      else if (db == 0.0) p = b;
      else p = a + (da / (da - db)) * (b - a);  // da, db of opposite signs: no division by 0
      it->second = {p[u] / scale, p[v] / scale};
    }
    return it->second;
  };

  // One directed segment per cut triangle, from the edge where the boundary (walked in the
  // triangle's outward orientation) enters the negative side to the edge where it leaves it:
  // neighbouring triangles then chain head to tail.
  std::map<Key, Key> next, prev;
  for (const auto& t : triangles) {
    Key enter{-1, -1}, leave{-1, -1};
    for (int c = 0; c < 3; ++c) {
      const int i = t[c], j = t[(c + 1) % 3];
      const bool pi = q[i][axis] >= 0.0, pj = q[j][axis] >= 0.0;
      if (pi && !pj) enter = edge_key(i, j);
      else if (!pi && pj) leave = edge_key(i, j);
    }
    if (enter.first < 0) continue;  // not cut (all on one side)
    next[enter] = leave;
    prev[leave] = enter;
  }

  std::vector<Polyline> out;
  std::map<Key, bool> used;
  auto trace = [&](Key start) {
    Polyline line;
    Key k = start;
    while (true) {
      used[k] = true;
      const auto p = point_of(k);
      // Consecutive points closer than eps (a vertex on or within rounding of the plane, reached
      // through several of its edges) are one point.
      if (line.points.empty() || std::hypot(line.points.back()[0] - p[0], line.points.back()[1] - p[1]) > eps)
        line.points.push_back(p);
      const auto it = next.find(k);
      if (it == next.end()) break;  // open chain ends here
      k = it->second;
      if (k == start) {
        line.closed = true;
        break;
      }
      if (used.count(k)) break;  // a non-manifold junction: stop rather than loop forever
    }
    if (line.closed && line.points.size() > 1 &&
        std::hypot(line.points.front()[0] - line.points.back()[0], line.points.front()[1] - line.points.back()[1]) <= eps)
      line.points.pop_back();
    if (line.closed) {
      double area2 = 0;  // twice the signed area
      for (std::size_t i = 0; i < line.points.size(); ++i) {
        const auto& a = line.points[i];
        const auto& b = line.points[(i + 1) % line.points.size()];
        area2 += a[0] * b[1] - b[0] * a[1];
      }
      if (area2 < 0) std::reverse(line.points.begin() + 1, line.points.end());
    }
    out.push_back(std::move(line));
  };
  // Open chains first, from their free ends; then the loops.
  for (const auto& [k, n] : next)
    if (!prev.count(k) && !used.count(k)) trace(k);
  for (const auto& [k, n] : next)
    if (!used.count(k)) trace(k);
  return out;
}

}  // namespace

CentralSlices central_slices(const Mesh& mesh, double scale) {
  if (!(scale > 0.0) || !std::isfinite(scale)) throw std::invalid_argument("central_slices: scale must be positive");
  const InertiaDeformation d = inertia_deformation(mesh);
  CentralSlices out;
  out.theta = d.theta;
  out.centroid = d.centroid;
  // Rotation about z by -theta, about the centroid.
  const double c = std::cos(d.theta), s = std::sin(d.theta);
  std::vector<Vec3> q;
  q.reserve(mesh.x.size());
  double size = 0;
  for (const auto& p : mesh.x) {
    const Vec3 r = p - d.centroid;
    q.emplace_back(c * r.x() + s * r.y(), -s * r.x() + c * r.y(), r.z());
    size = std::max(size, r.norm());
  }
  const double eps = 1e-12 * size / scale;  // rounding level of the scaled coordinates
  out.xy = section(q, mesh.triangles, 2, 0, 1, scale, eps);
  out.yz = section(q, mesh.triangles, 0, 2, 1, scale, eps);
  return out;
}

Mesh mesh_from_arrays(const std::vector<double>& xyz, const std::vector<int>& triangles) {
  if (xyz.empty() || xyz.size() % 3 != 0)
    throw std::invalid_argument("mesh_from_arrays: xyz has " + std::to_string(xyz.size()) +
                                " values, not a positive multiple of 3");
  if (triangles.empty() || triangles.size() % 3 != 0)
    throw std::invalid_argument("mesh_from_arrays: triangles has " + std::to_string(triangles.size()) +
                                " indices, not a positive multiple of 3");
  Mesh m;
  const int n = static_cast<int>(xyz.size() / 3);
  m.x.reserve(n);
  for (int i = 0; i < n; ++i) m.x.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  m.triangles.reserve(triangles.size() / 3);
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    Triangle tri{triangles[t], triangles[t + 1], triangles[t + 2]};
    for (int i : tri)
      if (i < 0 || i >= n)
        throw std::invalid_argument("mesh_from_arrays: triangle " + std::to_string(t / 3) + " has vertex index " +
                                    std::to_string(i) + " outside [0, " + std::to_string(n) + ")");
    m.triangles.push_back(tri);
  }
  build_topology(m);
  return m;
}

}  // namespace capsule::membrane3d
