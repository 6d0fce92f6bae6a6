#include "solver/membrane3d/elasticity.hpp"

#include "solver/membrane3d/surface_shear_rate.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsule::membrane3d {

namespace {
// The Maxwell element's law: the elastic law with E_s -> E_m, and Skalak's without its area term
// (C = 0) unless the element keeps it (MaxwellElement::skalak_area_term, physics version 5): the
// membrane viscosity is a shear viscosity, the area constant the elastic branch's. With C the
// element's instantaneous area modulus is E_m (1 + 2 C), 50 x 201 times the shear modulus at
// G = 50 and C = 100: a biconcave cell blew up within the first output interval, at rest and in
// shear (docs/findings/experiments.md "Recovery after release").
template <class Law>
Law maxwell_law_of(Law law, const MaxwellElement& m) {
  law.E_s = m.E_m;
  if constexpr (requires { law.C; })
    if (!m.skalak_area_term) law.C = 0.0;
  return law;
}
}  // namespace

ElasticMembrane::ElasticMembrane(const Mesh& ref, const Constitutive& law, const MaxwellElement& maxwell)
    : law_(law), maxwell_(maxwell) {
  const int nt = ref.triangle_count();
  Dm_inv_.resize(nt);
  area0_.resize(nt);
  for (int t = 0; t < nt; ++t) {
    const auto& tri = ref.triangles[t];
    const Vec3 e1 = ref.x[tri[1]] - ref.x[tri[0]], e2 = ref.x[tri[2]] - ref.x[tri[0]];
    // Plane frame of the reference triangle: x along edge ij (Fig. 3).
    const Vec3 ux = e1.normalized();
    const Vec3 uy = (e1.cross(e2)).cross(e1).normalized();
    Mat2 Dm;
    Dm << e1.dot(ux), e2.dot(ux), e1.dot(uy), e2.dot(uy);
    area0_[t] = 0.5 * Dm.determinant();  // (53)
    if (!(area0_[t] > 0)) throw std::runtime_error("elasticity: degenerate reference triangle");
    Dm_inv_[t] = Dm.inverse();
  }
  if (maxwell_.E_m > 0) {
    if (!(maxwell_.tau_m > 0) || !(maxwell_.dt > 0)) throw std::invalid_argument("SLS needs tau_m > 0 and dt > 0");
    Q_.assign(nt, Mat2::Zero());
    Sm_previous_.assign(nt, Mat2::Zero());
    const PowerLawRelaxation& pl = maxwell_.power_law;
    if (pl.on) {
      if (!(pl.shear_rate > 0) || !(pl.n > 0) || !(pl.gamma_floor > 0))
        throw std::invalid_argument("power-law SLS needs k > 0, n > 0 and gamma_floor > 0");
      C_previous_.assign(nt, Mat2::Identity());
    }
  }
}

std::vector<double> ElasticMembrane::memory() const {
  const bool power_law = maxwell_.power_law.on;
  std::vector<double> flat;
  flat.reserve((power_law ? 12 : 8) * Q_.size());
  for (std::size_t t = 0; t < Q_.size(); ++t) {
    for (int k = 0; k < 4; ++k) flat.push_back(Q_[t](k % 2, k / 2));
    for (int k = 0; k < 4; ++k) flat.push_back(Sm_previous_[t](k % 2, k / 2));
    if (power_law)
      for (int k = 0; k < 4; ++k) flat.push_back(C_previous_[t](k % 2, k / 2));
  }
  return flat;
}

void ElasticMembrane::restore_memory(const std::vector<double>& flat, bool started) {
  const bool power_law = maxwell_.power_law.on;
  const std::size_t per = power_law ? 12 : 8;
  if (flat.size() != per * Q_.size()) throw std::invalid_argument("ElasticMembrane::restore_memory: the saved SLS memory does not fit");
  for (std::size_t t = 0; t < Q_.size(); ++t) {
    for (int k = 0; k < 4; ++k) Q_[t](k % 2, k / 2) = flat[per * t + k];
    for (int k = 0; k < 4; ++k) Sm_previous_[t](k % 2, k / 2) = flat[per * t + 4 + k];
    if (power_law)
      for (int k = 0; k < 4; ++k) C_previous_[t](k % 2, k / 2) = flat[per * t + 8 + k];
  }
  memory_started_ = started;
}

double ElasticMembrane::reference_total_area() const {
  double a = 0;
  for (double x : area0_) a += x;
  return a;
}

Mat2 ElasticMembrane::cauchy_green(const Mesh& cur, int t) const {
  const auto& tri = cur.triangles[t];
  Eigen::Matrix<double, 3, 2> Ds;
  Ds.col(0) = cur.x[tri[1]] - cur.x[tri[0]];
  Ds.col(1) = cur.x[tri[2]] - cur.x[tri[0]];
  const Eigen::Matrix<double, 3, 2> F = Ds * Dm_inv_[t];
  return F.transpose() * F;
}

template <class TensionFn>
void ElasticMembrane::accumulate(const Mesh& cur, std::vector<Vec3>& force, TensionFn&& tension) const {
  const int nt = cur.triangle_count();
  std::vector<std::array<Vec3, 3>>& tri_force = tri_force_;
  tri_force.resize(nt);
  // Threads from level 3 on: a 3D member gets every core (study), and at level 4 on an idle
  // 2-core machine this pass went 0.36 -> 0.30-0.34 ms per step with 2 threads (the fork costs
  // microseconds); the forces are summed per vertex in a fixed order, so the result is bitwise
  // the same for any thread count.
#pragma omp parallel for schedule(static) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const auto& tri = cur.triangles[t];
    Eigen::Matrix<double, 3, 2> Ds;
    Ds.col(0) = cur.x[tri[1]] - cur.x[tri[0]];
    Ds.col(1) = cur.x[tri[2]] - cur.x[tri[0]];
    const Eigen::Matrix<double, 3, 2> F = Ds * Dm_inv_[t];
    const Mat2 S = tension(t, Mat2(F.transpose() * F));
    // (55): f_l = -A_0 F S grad N^l; the gradients of N^j, N^k are the rows of D_m^-1.
    const Eigen::Matrix<double, 3, 2> H = -area0_[t] * F * S * Dm_inv_[t].transpose();
    tri_force[t][1] = H.col(0);
    tri_force[t][2] = H.col(1);
    tri_force[t][0] = -(tri_force[t][1] + tri_force[t][2]);
  }
  const int nv = cur.vertex_count();
#pragma omp parallel for schedule(static) if (nv > 512)
  for (int v = 0; v < nv; ++v) {
    for (std::size_t n = 0; n < cur.vertex_triangles[v].size(); ++n)
      force[v] += tri_force[cur.vertex_triangles[v][n]][cur.corner_in_triangle[v][n]];
  }
}

void ElasticMembrane::add_elastic_forces(const Mesh& cur, std::vector<Vec3>& force) const {
  visit_law(law_, [&](const auto& law) {
    if (maxwell_.E_m > 0 && memory_started_) {
      accumulate(cur, force, [&](int t, const Mat2& C) { return Mat2(law.second_piola_kirchhoff(C) + Q_[t]); });
    } else {
      accumulate(cur, force, [&](int, const Mat2& C) { return law.second_piola_kirchhoff(C); });
    }
  });
}

void ElasticMembrane::add_forces(const Mesh& cur, std::vector<Vec3>& force) {
  if (!(maxwell_.E_m > 0)) {
    add_elastic_forces(cur, force);
    return;
  }
  if (maxwell_.power_law.on) {
    add_power_law_forces(cur, force);
    return;
  }
  const double decay = std::exp(-maxwell_.dt / maxwell_.tau_m);
  const double gain = maxwell_.tau_m / maxwell_.dt * (1.0 - decay);
  const bool started = memory_started_;
  visit_law(law_, [&](const auto& law) {
    const auto maxwell_law = maxwell_law_of(law, maxwell_);
    accumulate(cur, force, [&](int t, const Mat2& C) {
      const Mat2 Sm = maxwell_law.second_piola_kirchhoff(C);
      // (67); on the first call the memory starts from the current state (no jump: Q = 0).
      if (started) Q_[t] = decay * Q_[t] + gain * (Sm - Sm_previous_[t]);
      Sm_previous_[t] = Sm;
      return Mat2(law.second_piola_kirchhoff(C) + Q_[t]);
    });
  });
  memory_started_ = true;
}

// The SLS step (67) with each triangle's relaxation time from its surface viscosity (102) at
// its surface shear rate (101) over this step (elasticity.hpp, PowerLawRelaxation).
void ElasticMembrane::add_power_law_forces(const Mesh& cur, std::vector<Vec3>& force) {
  const PowerLawRelaxation& pl = maxwell_.power_law;
  const double dt = maxwell_.dt;
  const bool started = memory_started_;
  gamma_.resize(cur.triangle_count());
  visit_law(law_, [&](const auto& law) {
    const auto maxwell_law = maxwell_law_of(law, maxwell_);
    accumulate(cur, force, [&](int t, const Mat2& C) {
      const Mat2 Sm = maxwell_law.second_piola_kirchhoff(C);
      if (started) {
        const double gamma = surface_shear_rate(C_previous_[t], C, dt) / pl.shear_rate;  // (101), units of k
        gamma_[t] = gamma;
        const double tau = maxwell_.tau_m * std::pow(std::max(gamma, pl.gamma_floor), pl.n - 1.0);  // (102)
        const double decay = std::exp(-dt / tau);
        const double gain = tau / dt * (1.0 - decay);
        Q_[t] = decay * Q_[t] + gain * (Sm - Sm_previous_[t]);  // (67)
      } else {
        gamma_[t] = 0.0;  // the memory starts from the current state, as in add_forces
      }
      Sm_previous_[t] = Sm;
      C_previous_[t] = C;
      return Mat2(law.second_piola_kirchhoff(C) + Q_[t]);
    });
  });
  memory_started_ = true;
}

double ElasticMembrane::energy(const Mesh& cur) const {
  return visit_law(law_, [&](const auto& law) {
    double e = 0;
    for (int t = 0; t < cur.triangle_count(); ++t) e += area0_[t] * law.energy_density(cauchy_green(cur, t));
    return e;
  });
}

}  // namespace capsule::membrane3d
