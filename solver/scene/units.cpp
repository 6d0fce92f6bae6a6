#include "solver/scene/units.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/membrane3d/constitutive_law.hpp"

namespace capsule {

namespace {
// The relaxation-time rule (docs/guide/model.md "Relaxation time"). With Re = k a^2 / nu fixed, a larger
// nu means fewer steps per kt (steps_per_kt = a^2 / (Re nu)), but:
//  - accuracy: steady-state D_xy hardly depends on tau. Circle, a = 10, Ca = 0.05, E_b = 0.05,
//    D_xy at kt = 2.75: 0.274730 / 0.274729 / 0.274740 for tau = 0.7 / 1.0 / 1.5, area drift
//    -3e-6 / 3e-7 / -4e-5 (a = 5, E_b = 0: 0.39094 ... 0.39129 for tau = 0.6 ... 2.0, area drift
//    growing to -1.8e-3 at tau = 2). The resolution error (convergence study) is ~1e-3.
//  - stability of the explicit membrane coupling, governed by the membrane moduli over the
//    fluid viscosity: elastic S = E_s / nu = Re nu / (a Ca), bending B = E_B / (a^2 nu) * a
//    = E_b a Re nu / Ca. Measured with E_b = 0.05, Ca = 0.05: a = 5: tau = 2 (S = 0.10, B = 0.125)
//    runs, tau = 2.5 (S = 0.13, B = 0.17) blows up; a = 10: tau = 1.5 (S = 0.033, B = 0.17) runs,
//    tau = 2 (S = 0.05, B = 0.25) blows up; a = 20: tau = 1 (S = 0.008, B = 0.17) runs.
// Rule: tau = 1 (nu = 1/6), lowered until S <= 0.04 and B <= 0.12, never below 0.52.
// Membrane viscosity is not part of the rule (mu_s / nu = eta a does not depend on tau): the
// Kelvin-Voigt term (31) is taken implicitly in the node velocities and runs eta up to 20 at
// a = 10 (docs/guide/model.md "The 2D capsule").
double choose_tau_2d(const Scene& scene) {
  constexpr double nu_default = 1.0 / 6.0, S_max = 0.04, B_max = 0.12, tau_min = 0.52;
  double nu = std::min(nu_default, S_max * scene.resolution.a * scene.Ca / scene.Re);
  const double E_b = dimensionless_E_b(scene);
  if (E_b > 0) nu = std::min(nu, B_max * scene.Ca / (E_b * scene.resolution.a * scene.Re));
  return std::max(tau_min, 0.5 + 3.0 * nu);
}


// 3D (docs/guide/model.md "Relaxation time"): tau = 1.5 (nu = 1/3, half the steps per kt
// of tau = 1) for a capsule no more viscous than its surroundings, lowered where the explicit
// membrane coupling has not been seen stable. Measured at a = 5, level 3:
//  - accuracy (shear to kt 3, E_b = 0): the largest deviation of D_xy(kt >= 0.5) from tau = 1
//    is 0.27 / 0.33 / 0.13 % at Ca = 0.05 / 0.1 / 0.2 for tau = 1.5, and 0.42 / 0.60 / 0.27 %
//    for tau = 2; eta = 10: 0.26 % at tau = 1.5. The shear-and-recovery member (Ca = 0.05,
//    E_b = 0.025): D_stop, k tau_s, k tau_r move by -0.29 / -0.40 / -0.47 % at tau = 1.5 and
//    -0.97 / -1.17 / -1.27 % at tau = 2. So 1.5 is the largest tau tried within 0.5 %.
//  - a more viscous interior (V > 1) keeps tau = 1: at V = 5, D_xy(kt = 3) is 0.2059 / 0.2183 /
//    0.2329 for tau = 0.7 / 1 / 1.5 (the inside relaxation time 0.5 + 3 V nu is 1.5 / 3 / 5.5),
//    a tau-dependent error of several percent that no choice of tau keeps within 0.5 % of
//    tau = 1 (docs/guide/model.md "Relaxation time"); V = 2: +2.0 % at 1.5. The cause is the D3Q19 odd
//    moments' rates (their Lambda grows with the inside viscosity); resolution.collision = "trt"
//    removes it (docs/findings/accuracy_and_stability.md "Viscosity contrast and the relaxation
//    time"): with trt, D_stop moves by at most 0.01 % and k tau_s by 0.34 % over tau 0.7-1.5 at
//    V = 5 and 10, so a trt scene (the physics version 6 default) takes tau = 1.5 at any V; an
//    mrt scene (version 5) keeps tau = 1 for V > 1 so that its members' numbers do not move.
//  - stability: tau = 3 ran for Ca = 0.05 and 0.2 (S = Re nu/(a Ca) = 0.17 and 0.04); the
//    largest bending number B = E_b a Re nu/Ca seen stable is 0.17 (a = 10, tau = 1, E_b = 0.1,
//    Ca = 0.05). The 2D bounds (S 0.04, B 0.12) do not carry over: 3D ran stably at 4 x S.
//  - the Maxwell element (eta > 0, or the power law in the membrane): its stiffness E_m = G G_s
//    acts at once (tau_m is 10-60 steps), 50 times the elastic one at G = 50, and with Roma's
//    delta (the version 6 default, whose self-mobility is 2.4 times Peskin's) the explicit
//    coupling blows up when M = maxwell_stiffness_number is large, the sooner the finer the
//    membrane mesh. eta = 10, G = 50 (the dissertation's reading), Ca 0.05: level 3 blew up at
//    M = 1.32 and 1.07 (a = 4 and 5, tau 1.5) and ran at 0.8 to steady; a = 5, level 4 blew up
//    at 0.7 (kt 4.4), level 5 at 0.6 and 0.5 (kt 5.7 and 10.6) and ran to kt 20 at 0.4
//    (docs/guide/model.md "Relaxation time"). That bound, 0.4, holds under shear but not at rest:
//    a long recovery grows a slow mode (+0.41 per kt at M 0.4, a = 5, level 3; +0.59 at level 4;
//    +0.07 at M 0.22) until the membrane folds after 20-35 kt, while M 0.20 and 0.15 decay and
//    0.15 decays at levels 3-5, at a = 7 and over a 50 kt recovery; Peskin's delta decays at
//    0.4 (levels 3 and 4). docs/findings/accuracy_and_stability.md "A slow instability at rest".
//    So M_max = 0.4 for peskin4 and 0.15 for the other deltas (roma3 measured; linear2 and
//    cosine not, so they take the stricter bound).
double choose_tau_3d(const Scene& scene) {
  constexpr double nu_accurate = 1.0 / 3.0, nu_contrast = 1.0 / 6.0, S_max = 0.17, B_max = 0.17, tau_min = 0.52;
  const double M_max = maxwell_stiffness_bound(scene);
  double nu = (scene.V > 1.0 && scene.resolution.collision != lbm::CollisionModel::trt) ? nu_contrast : nu_accurate;
  nu = std::min(nu, S_max * scene.resolution.a * scene.Ca / scene.Re);
  if (scene.E_b > 0) nu = std::min(nu, B_max * scene.Ca / (scene.E_b * scene.resolution.a * scene.Re));
  // The Maxwell element's stiffness number M grows with nu (E_m ~ nu^2): lowered by bisection
  // until M <= M_max. Where even tau_min exceeds it (the Kelvin-Voigt limit, M -> eta a: no tau
  // helps), tau_min.
  const auto M = [&](double n) { return maxwell_stiffness_number(scene, 0.5 + 3.0 * n); };
  const double nu_min = (tau_min - 0.5) / 3.0;
  if (nu > nu_min && M(nu) > M_max) {
    double lo = nu_min, hi = nu;
    if (M(lo) > M_max) return tau_min;
    for (int i = 0; i < 60; ++i) (M(0.5 * (lo + hi)) > M_max ? hi : lo) = 0.5 * (lo + hi);
    nu = lo;
  }
  return std::max(tau_min, 0.5 + 3.0 * nu);
}
}  // namespace

membrane3d::ElasticLaw elastic_law_3d(MembraneLaw law) {
  switch (law) {
    case MembraneLaw::neo_hookean: return membrane3d::ElasticLaw::neo_hookean;
    case MembraneLaw::skalak: return membrane3d::ElasticLaw::skalak;
    case MembraneLaw::hooke: break;
  }
  throw std::invalid_argument("the law hooke is the 2D membrane's, not a 3D one");
}

membrane2d::ElasticLaw elastic_law_2d(MembraneLaw law) {
  switch (law) {
    case MembraneLaw::hooke: return membrane2d::ElasticLaw::hooke;
    case MembraneLaw::neo_hookean:
    case MembraneLaw::skalak: break;
  }
  throw std::invalid_argument("the law " + choice_name(law) + " is a 3D membrane's, not a 2D one");
}

double shear_modulus_3d(const Scene& s, const Units& u) {
  return membrane3d::law_modulus(elastic_law_3d(s.law), u.E_s);
}

MaxwellElement3d maxwell_element_3d(const Scene& s, const Units& u) {
  MaxwellElement3d m;
  const bool power_law_membrane = s.power_law.K > 0 && s.power_law.model == PowerLawModel::membrane;
  if (s.dim != 3 || !(s.eta > 0 || power_law_membrane)) return m;
  m.present = true;
  m.power_law = power_law_membrane;
  m.E_m = s.G * shear_modulus_3d(s, u);
  // rho = 1, so mu_a = nu; u.mu_s = eta a mu_a (36).
  const double mu = power_law_membrane ? s.power_law.K * s.resolution.a * u.nu
                                       : (s.conventions.sls_viscosity == SlsViscosity::dissertation ? u.mu_s / 3.0 : u.mu_s);
  m.tau_m = mu / m.E_m;
  return m;
}

double maxwell_stiffness_number(const Scene& s, double tau) {
  const Units u = units_for(s, tau);
  const MaxwellElement3d m = maxwell_element_3d(s, u);
  if (!m.present) return 0.0;
  if (m.power_law) return m.E_m / u.nu;
  return m.E_m * m.tau_m * (1.0 - std::exp(-1.0 / m.tau_m)) / u.nu;
}

double maxwell_stiffness_bound(const Scene& s) { return ib::maxwell_stiffness_bound(s.resolution.delta); }

double dimensionless_E_b(const Scene& s) {
  // The text's 2D reading (SceneConventions::E_b_2d): E_B = E_b a_text E_s with a_text = 0.5 in its units
  // of h = 0.05 (Sec. 2.4), so E_B / (a^2 E_s) = E_b / a_text = 2 E_b.
  if (s.dim == 2 && s.conventions.E_b_2d == BendingConvention2d::dissertation) return 2.0 * s.E_b;
  return s.E_b;
}

double membrane_bending_modulus(const Scene& s, const Units& u) {
  const double r_m = s.resolution.a - s.resolution.marker_inset;
  return dimensionless_E_b(s) * r_m * r_m * u.E_s;
}

double choose_tau(const Scene& scene) {
  if (scene.resolution.tau > 0) return scene.resolution.tau;
  return scene.dim == 2 ? choose_tau_2d(scene) : choose_tau_3d(scene);
}

Units units_for(const Scene& s, double tau) {
  if (!(tau > 0.5)) throw std::invalid_argument("relaxation time must exceed 1/2, got " + std::to_string(tau));
  Units u;
  u.tau = tau;
  u.nu = (tau - 0.5) / 3.0;                  // (8), (13)
  u.shear_rate = s.Re * u.nu / (s.resolution.a * s.resolution.a);  // Re = k a^2 / nu
  u.E_s = u.nu * u.shear_rate * s.resolution.a / s.Ca;  // (34) with mu_a = rho nu, rho = 1
  // (35) prints E_b = E_B / (a E_s), which is not dimensionless (E_B is an energy, E_s an
  // energy per area) and would make the physics depend on the resolution a. Sui et al.
  // (2008), whom Sec. 2.4.2 validates against with the same E_b values, use E_B / (a^2 E_s).
  u.E_B = dimensionless_E_b(s) * s.resolution.a * s.resolution.a * u.E_s;
  u.mu_s = s.eta * s.resolution.a * u.nu;               // (36)
  u.nu_inside = s.V * u.nu;
  u.steps_per_kt = 1.0 / u.shear_rate;
  return u;
}

}  // namespace capsule
