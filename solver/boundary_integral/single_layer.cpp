#include "solver/boundary_integral/single_layer.hpp"

#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace capsule::boundary_integral {

namespace m3 = membrane3d;

namespace {

// Boost's N-point Gauss-Legendre rule on [-1, 1] (it stores the non-negative half) mapped to [0, 1].
template <int N>
void gauss_on_unit_interval(std::vector<double>& x, std::vector<double>& w) {
  using rule = boost::math::quadrature::gauss<double, N>;
  const auto& a = rule::abscissa();
  const auto& b = rule::weights();
  x.clear();
  w.clear();
  for (std::size_t i = 0; i < a.size(); ++i) {
    x.push_back(0.5 * (1.0 + a[i]));
    w.push_back(0.5 * b[i]);
    if (a[i] != 0.0) {
      x.push_back(0.5 * (1.0 - a[i]));
      w.push_back(0.5 * b[i]);
    }
  }
}

// int over triangle (x0, x1, x2) of G(target - y) q(y) dS, q linear between q0, q1, q2, by
// Duffy's map from corner x0: y = x0 + u [(x1 - x0) + v (x2 - x1)]; barycentric weights
// (1 - u, u (1 - v), u v); dS = 2 A u du dv. With target == x0 the factor u cancels G's 1/u.
Vec3 duffy_integral(const Vec3& target, const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& q0,
                    const Vec3& q1, const Vec3& q2, const std::vector<double>& nodes, const std::vector<double>& weights,
                    bool target_is_x0) {
  const Vec3 e1 = x1 - x0, e21 = x2 - x1;
  const double twice_area = e1.cross(x2 - x0).norm();
  Vec3 sum = Vec3::Zero();
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const double u = nodes[a];
    for (std::size_t b = 0; b < nodes.size(); ++b) {
      const double v = nodes[b];
      const Vec3 w = e1 + v * e21;
      const Vec3 q = (1.0 - u) * q0 + u * (1.0 - v) * q1 + u * v * q2;
      // target == x0: G(-u w) u = G(w) (G even, homogeneous of degree -1).
      const Vec3 g = target_is_x0 ? stokeslet_apply(w, q) : (u * stokeslet_apply(target - (x0 + u * w), q));
      sum += (weights[a] * weights[b]) * g;
    }
  }
  return twice_area * sum;
}

void gauss_rule(int n, std::vector<double>& x, std::vector<double>& w, const char* option) {
  switch (n) {
    case 4: gauss_on_unit_interval<4>(x, w); break;
    case 6: gauss_on_unit_interval<6>(x, w); break;
    case 8: gauss_on_unit_interval<8>(x, w); break;
    case 12: gauss_on_unit_interval<12>(x, w); break;
    case 16: gauss_on_unit_interval<16>(x, w); break;
    default: throw std::invalid_argument(std::string("SingleLayer: ") + option + " must be 4, 6, 8, 12 or 16, got " + std::to_string(n));
  }
}

}  // namespace

SingleLayer::SingleLayer(SingleLayerOptions options) : options_(options) {
  gauss_rule(options_.singular_gauss_points, singular_nodes_, singular_weights_, "singular_gauss_points");
  gauss_rule(options_.near_gauss_points, near_nodes_, near_weights_, "near_gauss_points");
  if (!(options_.near_factor >= 0)) throw std::invalid_argument("SingleLayer: near_factor must be >= 0");
  if (!(options_.near_radius >= 0)) throw std::invalid_argument("SingleLayer: near_radius must be >= 0");
  if (!(options_.viscosity > 0)) throw std::invalid_argument("SingleLayer: viscosity must be > 0");
}

std::vector<double> lumped_vertex_areas(const m3::Mesh& mesh) {
  std::vector<double> A(mesh.vertex_count(), 0.0);
  for (const auto& t : mesh.triangles) {
    const double third = (mesh.x[t[1]] - mesh.x[t[0]]).cross(mesh.x[t[2]] - mesh.x[t[0]]).norm() / 6.0;
    for (int c : t) A[c] += third;
  }
  return A;
}

std::vector<Vec3> volume_gradient(const m3::Mesh& mesh) {
  std::vector<Vec3> g(mesh.vertex_count(), Vec3::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec3 area_vector = (mesh.x[t[1]] - mesh.x[t[0]]).cross(mesh.x[t[2]] - mesh.x[t[0]]);  // 2 A n
    for (int c : t) g[c] += area_vector / 6.0;
  }
  return g;
}

double remove_volume_flux(const m3::Mesh& mesh, std::vector<Vec3>& u) {
  const std::vector<Vec3> g = volume_gradient(mesh);
  double ug = 0, gg = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    ug += u[i].dot(g[i]);
    gg += g[i].squaredNorm();
  }
  const double lambda = ug / gg;
  for (std::size_t i = 0; i < g.size(); ++i) u[i] -= lambda * g[i];
  return lambda;
}

void SingleLayer::velocity(const m3::Mesh& mesh, const std::vector<Vec3>& q, std::vector<Vec3>& u) const {
  const int nv = mesh.vertex_count(), nt = mesh.triangle_count();
  if (static_cast<int>(q.size()) != nv) throw std::invalid_argument("SingleLayer: one density per vertex needed");
  const std::vector<double> A = lumped_vertex_areas(mesh);
  std::vector<Vec3> F(nv);  // the trapezoid rule's point forces
  for (int j = 0; j < nv; ++j) F[j] = q[j] * A[j];
  // Per triangle: centroid, squared near radius, a third of its area.
  std::vector<Vec3> centroid(nt);
  std::vector<double> near2(nt), third_area(nt);
  for (int t = 0; t < nt; ++t) {
    const auto& c = mesh.triangles[t];
    const Vec3 &a = mesh.x[c[0]], &b = mesh.x[c[1]], &d = mesh.x[c[2]];
    centroid[t] = (a + b + d) / 3.0;
    const double longest = std::max({(b - a).norm(), (d - b).norm(), (a - d).norm()});
    near2[t] = std::pow(std::max(options_.near_factor * longest, options_.near_radius), 2);
    third_area[t] = (b - a).cross(d - a).norm() / 6.0;
  }
  u.assign(nv, Vec3::Zero());
  const double scale = 1.0 / (8.0 * std::numbers::pi * options_.viscosity);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nv; ++i) {
    const Vec3 xi = mesh.x[i];
    Vec3 sum = Vec3::Zero();
    for (int j = 0; j < nv; ++j)
      if (j != i) sum += stokeslet_apply(xi - mesh.x[j], F[j]);
    for (int t = 0; t < nt; ++t) {
      const auto& c = mesh.triangles[t];
      const int corner = c[0] == i ? 0 : c[1] == i ? 1 : c[2] == i ? 2 : -1;
      if (corner < 0 && (xi - centroid[t]).squaredNorm() >= near2[t]) continue;
      // Replace this triangle's share of the trapezoid sum by the accurate integral.
      for (int k : c)
        if (k != i) sum -= stokeslet_apply(xi - mesh.x[k], q[k] * third_area[t]);
      int start = corner;
      if (start < 0) {  // map from the corner nearest to the target
        start = 0;
        for (int k = 1; k < 3; ++k)
          if ((mesh.x[c[k]] - xi).squaredNorm() < (mesh.x[c[start]] - xi).squaredNorm()) start = k;
      }
      const int c0 = c[start], c1 = c[(start + 1) % 3], c2 = c[(start + 2) % 3];
      const bool singular = corner >= 0;
      sum += duffy_integral(xi, mesh.x[c0], mesh.x[c1], mesh.x[c2], q[c0], q[c1], q[c2],
                            singular ? singular_nodes_ : near_nodes_, singular ? singular_weights_ : near_weights_, singular);
    }
    u[i] = scale * sum;
  }
}

}  // namespace capsule::boundary_integral
