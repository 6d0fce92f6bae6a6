// The optical-tweezers load (solver/membrane3d/optical_tweezers.hpp): the beads' forces balance,
// +F and -F along x, on symmetric patches of the stated size; the diameters against brute force.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "solver/membrane3d/optical_tweezers.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "solver/membrane3d/surface_geometry.hpp"

using namespace capsule::membrane3d;

namespace {

// The total force and torque (about the vertices' centroid) of the beads' forces alone.
struct Resultant {
  Vec3 plus = Vec3::Zero(), minus = Vec3::Zero(), torque = Vec3::Zero();
};
Resultant resultant(const Mesh& m, const PulledPatches& p, double F) {
  std::vector<Vec3> f(m.vertex_count(), Vec3::Zero());
  add_pulling_forces(p, F, f);
  Vec3 c = Vec3::Zero();
  for (const Vec3& x : m.x) c += x;
  c /= m.vertex_count();
  Resultant r;
  for (int v : p.plus) r.plus += f[v];
  for (int v : p.minus) r.minus += f[v];
  for (int v = 0; v < m.vertex_count(); ++v) r.torque += (m.x[v] - c).cross(f[v]);
  return r;
}

}  // namespace

TEST_CASE("the beads pull with +F and -F along x: the forces sum to zero and exert no torque", "[membrane3d][stretch]") {
  const Mesh sphere = sphere_mesh(unit_icosphere(3), 5.0);
  const Mesh cell = biconcave_mesh(unit_icosphere(3), 5.0);  // disc in the xz-plane, as a stretch scene lays it
  const double F = 0.37;
  for (const Mesh* m : {&sphere, &cell}) {
    for (const PulledPatches& p : {patches_by_fraction(*m, 0.02), patches_by_contact_diameter(*m, 2.0)}) {
      const Resultant r = resultant(*m, p, F);
      // Each share is A_i / sum A, so each bead's force is F to rounding (a few ulp of F).
      CHECK(r.plus.x() == Approx(F).epsilon(1e-14));
      CHECK(r.minus.x() == Approx(-F).epsilon(1e-14));
      CHECK(std::abs(r.plus.x() + r.minus.x()) < 1e-15);
      CHECK(r.plus.tail<2>().norm() == 0.0);
      CHECK(r.minus.tail<2>().norm() == 0.0);
      // The mesh is symmetric under x -> -x and the patches keep their ties: no couple.
      CHECK(r.torque.norm() < 1e-13 * F * 5.0);
      CHECK(p.plus.size() == p.minus.size());
      CHECK(p.plus_area == Approx(p.minus_area).epsilon(1e-12));
    }
  }
}

TEST_CASE("a patch holds the stated fraction of the vertices or lies within the contact diameter", "[membrane3d][stretch]") {
  const Mesh m = sphere_mesh(unit_icosphere(3), 5.0);  // 642 vertices
  const PulledPatches by_fraction = patches_by_fraction(m, 0.02);
  // round(0.02 x 642) = 13 vertices, with any ties of the 13th.
  CHECK(by_fraction.plus.size() >= 13);
  CHECK(by_fraction.plus.size() <= 14);
  for (int v : by_fraction.plus) CHECK(m.x[v].x() > 4.0);
  for (int v : by_fraction.minus) CHECK(m.x[v].x() < -4.0);
  const PulledPatches by_contact = patches_by_contact_diameter(m, 3.0);
  double hi = 0;
  for (const Vec3& x : m.x) hi = std::max(hi, x.x());
  for (int v : by_contact.plus) CHECK((m.x[v] - Vec3(hi, 0, 0)).norm() <= 1.5 * (1 + 1e-9));
  // A contact diameter below the mesh spacing still catches the nearest vertex (and its ties).
  CHECK(!patches_by_contact_diameter(m, 1e-6).plus.empty());
  // The shares follow the Voronoi areas and sum to 1.
  const std::vector<double> areas = voronoi_areas(m);
  CHECK(std::accumulate(by_fraction.plus_share.begin(), by_fraction.plus_share.end(), 0.0) == Approx(1.0).epsilon(1e-14));
  CHECK(by_fraction.plus_share[0] == Approx(areas[by_fraction.plus[0]] / by_fraction.plus_area).epsilon(1e-14));
  CHECK_THROWS(patches_by_fraction(m, 0.5));
  CHECK_THROWS(patches_by_fraction(m, 0.0));
}

TEST_CASE("the axial and transverse diameters are the extent along x and the widest pair in the y-z plane", "[membrane3d][stretch]") {
  Mesh m = biconcave_mesh(unit_icosphere(3), 4.0);
  for (Vec3& x : m.x) x = Vec3(1.3 * x.x() + 0.2 * x.y(), 0.7 * x.y(), 0.9 * x.z() - 0.1 * x.y());  // no symmetry left
  double hi = -1e9, lo = 1e9, widest = 0;
  for (const Vec3& a : m.x) {
    hi = std::max(hi, a.x()), lo = std::min(lo, a.x());
    for (const Vec3& b : m.x) widest = std::max(widest, std::hypot(a.y() - b.y(), a.z() - b.z()));
  }
  const StretchDiameters d = stretch_diameters(m);
  CHECK(d.axial == Approx(hi - lo).epsilon(1e-15));
  CHECK(d.transverse == Approx(widest).epsilon(1e-14));
  // The icosphere has vertices on the great circle x = 0: a sphere's transverse diameter is 2R.
  CHECK(stretch_diameters(sphere_mesh(unit_icosphere(3), 5.0)).transverse == Approx(10.0).epsilon(1e-13));
}
