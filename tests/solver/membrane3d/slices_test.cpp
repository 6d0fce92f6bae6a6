// Central slices (Figs. 41-53, Sec. 4.2): sections of the capsule mapped to theta = 0 by the
// planes z = z_c (xy) and x = x_c (yz), checked on a sphere, an inclined ellipsoid and the
// inclined biconcave shape.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/membrane3d/shapes.hpp"
#include "solver/membrane3d/slices.hpp"

using namespace capsule::membrane3d;
namespace {
constexpr double pi = std::numbers::pi;

// Largest angle subtended at `c` by a mesh edge (for a sphere about c: the chord angle).
double max_edge_angle(const Mesh& m, const Vec3& c) {
  double phi = 0;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = (m.x[t[k]] - c).normalized(), b = (m.x[t[(k + 1) % 3]] - c).normalized();
      phi = std::max(phi, std::acos(std::clamp(a.dot(b), -1.0, 1.0)));
    }
  return phi;
}

// Smallest distance from `c` to the plane of a face.
double min_face_distance(const Mesh& m, const Vec3& c) {
  double h = std::numeric_limits<double>::infinity();
  for (const auto& t : m.triangles) {
    const Vec3 n = (m.x[t[1]] - m.x[t[0]]).cross(m.x[t[2]] - m.x[t[0]]).normalized();
    h = std::min(h, std::abs(n.dot(m.x[t[0]] - c)));
  }
  return h;
}

double perimeter(const Polyline& l) {
  double s = 0;
  for (std::size_t i = 0; i < l.points.size(); ++i) {
    const auto& a = l.points[i];
    const auto& b = l.points[(i + 1) % l.points.size()];
    s += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  return s;
}

struct Extent {
  double lo_u = std::numeric_limits<double>::infinity(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
  double du() const { return hi_u - lo_u; }
  double dv() const { return hi_v - lo_v; }
};
Extent extent(const Polyline& l) {
  Extent e;
  for (const auto& p : l.points) {
    e.lo_u = std::min(e.lo_u, p[0]);
    e.hi_u = std::max(e.hi_u, p[0]);
    e.lo_v = std::min(e.lo_v, p[1]);
    e.hi_v = std::max(e.hi_v, p[1]);
  }
  return e;
}

// Height (max v - min v) of a closed loop along the vertical line u = u0.
double thickness_at(const Polyline& l, double u0) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < l.points.size(); ++i) {
    const auto& a = l.points[i];
    const auto& b = l.points[(i + 1) % l.points.size()];
    if ((a[0] - u0) * (b[0] - u0) > 0 || a[0] == b[0]) continue;
    const double v = a[1] + (u0 - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return hi - lo;
}

double signed_area(const Polyline& l) {
  double s = 0;
  for (std::size_t i = 0; i < l.points.size(); ++i) {
    const auto& a = l.points[i];
    const auto& b = l.points[(i + 1) % l.points.size()];
    s += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * s;
}
}  // namespace

TEST_CASE("central slices of a sphere are circles of radius R within the chord error", "[membrane3d][slices]") {
  const double R = 7.0;
  const Vec3 centre(30.0, 20.0, 10.0);
  double previous_bound = std::numeric_limits<double>::infinity(), previous_error = previous_bound;
  for (int level : {3, 4}) {
    INFO("level " << level);
    Mesh m = sphere_mesh(unit_icosphere(level), R);
    rotate_about_z_and_translate(m, 0.0, centre);
    // Slice points lie on mesh edges, i.e. on chords of the sphere: a chord subtending phi lies
    // between R cos(phi/2) and R from the centre, so with phi_max the largest edge angle every
    // point is within R (1 - cos(phi_max/2)) of the sphere (in units of R: scale = R).
    const double phi = max_edge_angle(m, centre);
    const double radius_bound = 1.0 - std::cos(0.5 * phi);
    // The icosphere is convex, so each slice is a convex polygon inside the unit circle and
    // containing the disk of radius h (nearest face plane): 2 pi h <= perimeter <= 2 pi.
    const double h = min_face_distance(m, centre) / R;
    const CentralSlices s = central_slices(m, R);
    CHECK((s.centroid - centre).norm() < 1e-9 * R);  // rounding only: the icosphere is centrally symmetric
    double max_error = 0;
    for (const auto* loops : {&s.xy, &s.yz}) {
      REQUIRE(loops->size() == 1);
      const Polyline& l = loops->front();
      double r_min = 1.0, r_max = 0.0;
      for (const auto& p : l.points) {
        r_min = std::min(r_min, std::hypot(p[0], p[1]));
        r_max = std::max(r_max, std::hypot(p[0], p[1]));
      }
      max_error = std::max(max_error, 1.0 - r_min);
      const double P = perimeter(l);
      INFO("phi_max = " << phi << ", radius bound " << radius_bound << ", radii in [" << r_min << ", " << r_max
                        << "], perimeter/(2 pi R) - 1 = " << P / (2 * pi) - 1 << ", bound " << 1 - h);
      CHECK(l.closed);
      CHECK(l.points.size() > 20);
      CHECK(signed_area(l) > 0);  // counter-clockwise, as documented
      CHECK(r_max <= 1.0 + 1e-12);
      CHECK(r_min >= 1.0 - radius_bound - 1e-12);
      CHECK(P <= 2 * pi + 1e-12);
      CHECK(P >= 2 * pi * h - 1e-12);
    }
    CHECK(radius_bound < previous_bound / 3);  // halving the edges quarters the chord error
    CHECK(max_error < previous_error);
    previous_bound = radius_bound;
    previous_error = max_error;
  }
}

TEST_CASE("central slices of an inclined ellipsoid show its semi-axes after mapping to theta = 0",
          "[membrane3d][slices]") {
  const double A = 1.6, B = 1.0, C = 0.7, angle = 0.4;
  const int level = 4;
  Mesh m = unit_icosphere(level);
  // Edge angles of the unit icosphere: the ellipsoid is its linear image diag(A, B, C).
  const double phi = max_edge_angle(m, Vec3::Zero());
  for (auto& p : m.x) p = Vec3(A * p.x(), B * p.y(), C * p.z());
  rotate_about_z_and_translate(m, angle, Vec3(40.0, 25.0, 12.0));
  const CentralSlices s = central_slices(m, 1.0);
  // The icosphere is mirror-symmetric in the coordinate planes, so the inertia axes of the
  // unrotated ellipsoid mesh are x, y, z exactly and theta is the rotation up to rounding.
  CHECK(s.theta == Approx(angle).margin(1e-9));
  REQUIRE(s.xy.size() == 1);
  REQUIRE(s.yz.size() == 1);
  CHECK(s.xy.front().closed);
  CHECK(s.yz.front().closed);
  // Mapped back, each slice is diag(.,.) of the unit icosphere's central slice, whose points lie
  // within [cos(phi/2), 1] of the centre (chords) and at most phi/2 in angle from any
  // direction (polygon edges lie in faces): so an extent 2X comes out in [2X cos^2(phi/2), 2X].
  const double rel = 1.0 - std::pow(std::cos(0.5 * phi), 2) + 1e-9;
  const Extent xy = extent(s.xy.front()), yz = extent(s.yz.front());
  INFO("ellipsoid level 4: theta = " << s.theta << ", xy extents " << xy.du() << " x " << xy.dv() << ", yz extents "
                                     << yz.du() << " x " << yz.dv() << ", tolerance " << rel << " relative");
  CHECK(xy.du() <= 2 * A * (1 + 1e-9));
  CHECK(xy.du() >= 2 * A * (1 - rel));
  CHECK(xy.dv() <= 2 * B * (1 + 1e-9));
  CHECK(xy.dv() >= 2 * B * (1 - rel));
  // yz slice: u = z, v = y.
  CHECK(yz.du() <= 2 * C * (1 + 1e-9));
  CHECK(yz.du() >= 2 * C * (1 - rel));
  CHECK(yz.dv() <= 2 * B * (1 + 1e-9));
  CHECK(yz.dv() >= 2 * B * (1 - rel));
  // Centred on the centroid.
  CHECK(xy.hi_u + xy.lo_u == Approx(0).margin(2 * A * rel));
  CHECK(yz.hi_v + yz.lo_v == Approx(0).margin(2 * B * rel));
}

TEST_CASE("central slices of the 45-degree biconcave capsule show the dimple in both planes",
          "[membrane3d][slices]") {
  // biconcave_mesh has its symmetry axis along y; inclined by 45 degrees its inertia major axis
  // (a disk diameter) is at theta = pi/4. Mapped back to theta = 0 the symmetry axis is y
  // again, so BOTH central slices contain it and both show the biconcave profile: thin at the
  // centre (analytic thickness 0.207 s alpha), thickest near the rim.
  const double a = 10.0;
  Mesh m = biconcave_mesh(unit_icosphere(4), a);
  rotate_about_z_and_translate(m, pi / 4, Vec3(50, 50, 40));
  const CentralSlices s = central_slices(m, a);
  CHECK(s.theta == Approx(pi / 4).margin(1e-9));
  REQUIRE(s.xy.size() == 1);
  REQUIRE(s.yz.size() == 1);
  const Polyline &xy = s.xy.front(), &yz = s.yz.front();
  REQUIRE(xy.closed);
  REQUIRE(yz.closed);
  const double sa = biconcave_scale_for_unit_equivalent_radius() * biconcave_alpha;  // disk radius / a
  const Extent exy = extent(xy), eyz = extent(yz);
  double rim_xy = 0, rim_yz = 0;
  for (double u = -0.95 * sa; u <= 0.95 * sa; u += 0.01 * sa) {
    rim_xy = std::max(rim_xy, thickness_at(xy, u));
    rim_yz = std::max(rim_yz, thickness_at(yz, u));
  }
  const double centre_xy = thickness_at(xy, 0.0), centre_yz = thickness_at(yz, 0.0);
  INFO("biconcave: diameter/a xy " << exy.du() << " yz " << eyz.du() << " (analytic " << 2 * sa
                                   << "); centre thickness/a " << centre_xy << " (analytic " << 0.207 * sa
                                   << "), max thickness/a xy " << rim_xy << " yz " << rim_yz);
  // Both slices pass through the line x = z = 0 of the mapped frame, which crosses the same two
  // triangles: the centre thickness is the same number in both (rounding only).
  CHECK(centre_xy == Approx(centre_yz).margin(1e-9));
  // Biconcavity: the analytic ratio centre/max thickness is about 0.25; the mesh blurs it by
  // chord errors of a few percent, so < 0.5 is a wide, still falsifiable bound (a convex
  // section has its maximum thickness at the centre, ratio 1).
  CHECK(centre_xy < 0.5 * rim_xy);
  CHECK(centre_yz < 0.5 * rim_yz);
  // Axisymmetry: the two slices are the same profile up to the mesh's chord error (about 1 %
  // of the diameter at level 4, where an edge subtends about 4 degrees).
  CHECK(exy.du() == Approx(eyz.du()).epsilon(0.01));
  CHECK(rim_xy == Approx(rim_yz).epsilon(0.03));
  CHECK(exy.du() <= 2 * sa * (1 + 1e-9));
  CHECK(exy.du() >= 2 * sa * 0.99);
  CHECK(centre_xy == Approx(0.207 * sa).epsilon(0.05));
}

TEST_CASE("mesh_from_arrays rebuilds a member file's shape and rejects bad arrays", "[membrane3d][slices]") {
  const Mesh ref = sphere_mesh(unit_icosphere(2), 3.0);
  std::vector<double> xyz;
  std::vector<int> tri;
  for (const auto& p : ref.x) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  for (const auto& t : ref.triangles) tri.insert(tri.end(), t.begin(), t.end());
  const Mesh m = mesh_from_arrays(xyz, tri);
  CHECK(m.vertex_count() == ref.vertex_count());
  CHECK(m.triangle_count() == ref.triangle_count());
  CHECK(m.edges.size() == ref.edges.size());
  const CentralSlices s = central_slices(m, 3.0);
  CHECK(s.xy.size() == 1);
  CHECK_THROWS_AS(mesh_from_arrays({1.0, 2.0}, tri), std::invalid_argument);
  std::vector<int> bad = tri;
  bad[4] = ref.vertex_count();
  CHECK_THROWS_AS(mesh_from_arrays(xyz, bad), std::invalid_argument);
  std::vector<int> open(tri.begin(), tri.end() - 3);  // one face missing: not closed
  CHECK_THROWS_AS(mesh_from_arrays(xyz, open), std::runtime_error);
  CHECK_THROWS_AS(central_slices(m, 0.0), std::invalid_argument);
}

TEST_CASE("a vertex exactly on the cutting plane gives one clean closed loop", "[membrane3d][slices]") {
  // The level-0 icosahedron has vertices (0, +-1, +-phi)/|.| etc.: with centroid 0 and theta = 0
  // (mirror symmetry, both up to rounding) the planes x = 0 and z = 0 each pass through four
  // vertices, exactly or within rounding: either way the loop must not repeat a point.
  const Mesh m = sphere_mesh(unit_icosphere(0), 1.0);
  const CentralSlices s = central_slices(m, 1.0);
  for (const auto* loops : {&s.xy, &s.yz}) {
    REQUIRE(loops->size() == 1);
    const Polyline& l = loops->front();
    CHECK(l.closed);
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      const auto& a = l.points[i];
      const auto& b = l.points[(i + 1) % l.points.size()];
      CHECK(std::hypot(b[0] - a[0], b[1] - a[1]) > 1e-12);  // no repeated points
    }
    CHECK(signed_area(l) > 0.5);  // a real polygon, counter-clockwise
  }
}
