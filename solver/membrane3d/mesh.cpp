#include "solver/membrane3d/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace capsule::membrane3d {

namespace {

Mesh icosahedron() {
  Mesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;  // golden ratio
  const double raw[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : raw) m.x.push_back(Vec3(p[0], p[1], p[2]).normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  return m;
}

void refine_once(Mesh& m) {
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    const int id = static_cast<int>(m.x.size());
    m.x.push_back((0.5 * (m.x[a] + m.x[b])).normalized());
    midpoint.emplace(key, id);
    return id;
  };
  std::vector<Triangle> refined;
  refined.reserve(4 * m.triangles.size());
  for (const auto& t : m.triangles) {
    const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    refined.push_back({t[0], ab, ca});
    refined.push_back({t[1], bc, ab});
    refined.push_back({t[2], ca, bc});
    refined.push_back({ab, bc, ca});
  }
  m.triangles = std::move(refined);
}

}  // namespace

Mesh unit_icosphere(int level) {
  if (level < 0 || level > 7) throw std::invalid_argument("mesh level must be in 0..7");
  Mesh m = icosahedron();
  for (int l = 0; l < level; ++l) refine_once(m);
  build_topology(m);
  return m;
}

void build_topology(Mesh& m) {
  const int nv = m.vertex_count();
  m.vertex_triangles.assign(nv, {});
  m.corner_in_triangle.assign(nv, {});
  m.ring.assign(nv, {});
  m.edges.clear();
  // Directed edges: each must appear exactly once, and its reverse exactly once.
  std::map<std::pair<int, int>, int> directed;
  for (int t = 0; t < m.triangle_count(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int a = m.triangles[t][c], b = m.triangles[t][(c + 1) % 3];
      if (!directed.emplace(std::make_pair(a, b), t).second)
        throw std::runtime_error("mesh: directed edge used twice (inconsistent orientation or non-manifold)");
      m.vertex_triangles[a].push_back(t);
      m.corner_in_triangle[a].push_back(c);
    }
  }
  for (const auto& [e, t] : directed) {
    (void)t;
    if (!directed.count({e.second, e.first})) throw std::runtime_error("mesh: open boundary edge");
    if (e.first < e.second) m.edges.push_back({e.first, e.second});
  }
  // Ordered one-ring: in triangle (v, a, b) (counter-clockwise from outside) the
  // neighbour after a going around v is b.
  for (int v = 0; v < nv; ++v) {
    std::map<int, int> next;
    for (std::size_t n = 0; n < m.vertex_triangles[v].size(); ++n) {
      const auto& t = m.triangles[m.vertex_triangles[v][n]];
      const int c = m.corner_in_triangle[v][n];
      next[t[(c + 1) % 3]] = t[(c + 2) % 3];
    }
    if (next.empty()) throw std::runtime_error("mesh: isolated vertex " + std::to_string(v));
    const int start = next.begin()->first;
    int cur = start;
    do {
      m.ring[v].push_back(cur);
      auto it = next.find(cur);
      if (it == next.end()) throw std::runtime_error("mesh: open one-ring");
      cur = it->second;
    } while (cur != start && m.ring[v].size() <= next.size());
    if (m.ring[v].size() != next.size()) throw std::runtime_error("mesh: one-ring is not a single fan");
  }
}

}  // namespace capsule::membrane3d
