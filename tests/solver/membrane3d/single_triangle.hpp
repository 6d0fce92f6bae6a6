#pragma once
// A one-triangle "mesh" for the membrane tests (no topology checks: it is open).
#include "solver/membrane3d/mesh.hpp"

namespace capsule::membrane3d::testing {

inline Mesh single_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Mesh m;
  m.x = {a, b, c};
  m.triangles = {{0, 1, 2}};
  m.vertex_triangles = {{0}, {0}, {0}};
  m.corner_in_triangle = {{0}, {1}, {2}};
  return m;
}

}  // namespace capsule::membrane3d::testing
