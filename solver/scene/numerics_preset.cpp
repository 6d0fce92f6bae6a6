#include "solver/scene/numerics_preset.hpp"

#include <cmath>

namespace capsule {

std::vector<NumericsItem> dissertation_numerics_items(int dim, Shape shape) {
  std::vector<NumericsItem> items;
  if (dim == 2 && shape == Shape::biconcave) {
    items = {
        {"Re", "0.025", "Sec. 2: Re = rho k a / mu_a = 0.05 with the printed a = 0.5 (Sec. 2.4), i.e. k a^2 / nu = 0.025"},
        {"resolution.a", "10", "Sec. 2, 2.4: h = dt = dx = 0.05 with the printed a = 0.5"},
        {"conventions.E_b_2d", "dissertation", "(35) with the printed a = 0.5: E_B = 2 E_b a^2 E_s"},
        {"conventions.biconcave_2d", "dissertation", "(24)-(25) drawn with the printed a = 0.5 (equivalent radius 0.740 a)"},
    };
  } else if (dim == 2) {
    items = {
        {"Re", "0.05", "Sec. 2: Re = rho k a / mu_a = 0.05 with the circle's radius a = 1, i.e. k a^2 / nu = 0.05"},
        {"resolution.a", "20",
         "Sec. 2: h = dt = dx = 0.05 with the circle's radius a = 1 (not printed; a = 0.5, 10 lattice units, makes the "
         "cosine delta stiffen a bending circle several times over: probe_cosine_lattice_2d)"},
        {"conventions.E_b_2d", "dimensionless", "(35) with a = 1: E_B = E_b a^2 E_s"},
    };
  }
  if (dim == 2) {
    const std::vector<NumericsItem> common = {
        {"resolution.domain", "[16, 12]", "Sec. 2: [0, 16a] x [0, 12a]"},
        {"resolution.segments", "140", "Sec. 2.4: 140 line segments, equal at start"},
        {"resolution.kernel", "cosine", "(17)-(18): the cosine delta"},
        {"resolution.marker_inset", "0", "Sec. 2.3-2.4: the markers on the membrane"},
        {"resolution.membrane_update", "euler", "(20): forward Euler with the interpolated velocity (19)"},
        {"resolution.collision", "mrt", "(6)-(10): the D2Q9 MRT rates (s_eps: see what is not emulated)"},
        {"resolution.precision", "double", "not stated; double, the toolkit's 2D default"},
    };
    items.insert(items.end(), common.begin(), common.end());
  } else {
    items = {
        {"Re", "0.05", "Sec. 2: Re = rho k a / mu_a = 0.05 with a = 1 (Sec. 2.6)"},
        {"resolution.a", "10", "Sec. 2: h = dt = dx = 0.1 with a = 1"},
        {"resolution.domain", "[10, 10, 8]", "Sec. 2: [0, 10a] x [0, 10a] x [0, 8a]"},
        {"resolution.mesh_level", "4", "Sec. 2.6: 2562 vertices, 5120 triangles"},
        {"resolution.kernel", "cosine", "(17)-(18): the cosine delta"},
        {"resolution.marker_inset", "0", "Sec. 2.3, 2.6: the markers on the membrane (radius a)"},
        {"resolution.membrane_update", "euler", "(20): forward Euler with the interpolated velocity (19)"},
        {"resolution.collision", "mrt", "(11)-(14): the D3Q19 MRT rates, q at s_nu, the ghost moments at 1.8"},
        {"resolution.precision", "double", "not stated; double, as every MRT code of its references"},
        {"conventions.sls_viscosity", "dissertation", "(63) read literally: the Kelvin-Voigt limit has mu_s / 3"},
        {"power_law.model", "fluid_shell", "(103)-(104): the power law spread over the lattice as fluid viscosity"},
    };
  }
  return items;
}

std::vector<NumericsGap> dissertation_numerics_gaps(int dim) {
  std::vector<NumericsGap> gaps = {
      {"the energy-square rate s_eps (s_2), printed 1.64 (D2Q9) / 1.8 (D3Q19)", "s_eps = s_nu",
       "with s_e = s_nu the printed value is linearly unstable at rest above tau 1.9 (D2Q9) / 1.5 (D3Q19), "
       "inside every capsule with V >= 2 at the toolkit's tau; eps enters no Navier-Stokes term "
       "(docs/guide/model.md \"Fluid\")"},
      {"the energy rate s_e (s_1), the bulk viscosity (10), (14)", "s_e = s_nu",
       "the text gives no bulk viscosity; any other s_e leaves a steady O(U^2) error in plane Couette flow"},
      {"the relaxation time tau", "the toolkit's rule, recorded as tau and tau_rule",
       "the text gives h = dt = dx but no lattice viscosity (docs/guide/model.md \"Relaxation time\")"},
      {"the forcing (22)-(23) and the viscosity contrast (15)-(16)", "the text's, in both numerics",
       "the toolkit runs them as printed"},
      {"the fit intervals, \"steady\" and \"recovered\"", "the campaign's protocol and the report's fits",
       "the campaigns stop the shear where the text does; the text does not say which interval each fit uses"},
  };
  if (dim == 2) {
    gaps.push_back({"how the Kelvin-Voigt tension (31) is stepped", "resolution.kelvin_voigt_step: exact_mobility",
                    "the text gives the one-sided second-order time derivative, not how the step is solved; "
                    "the approximate step gives the same D_xy within 1e-4 at eta <= 12 and blows up at eta >= 24 "
                    "(docs/findings/kelvin_voigt_2d.md)"});
    gaps.push_back({"the curvature (33), printed with F'''", "F'' / (1 + F'^2)^(3/2)",
                    "F''' is not a curvature: a misprint no run could have used"});
  } else {
    gaps.push_back({"the neo-Hookean law (56), (58) read as printed (G_s = E_s)", "G_s = E_s / 3",
                    "read as printed a sphere deforms about three times less than the curves the text matches "
                    "in Fig. 7 (docs/conventions.md \"Neo-Hookean modulus\")"});
    gaps.push_back({"the misprints of (11), (57), (79), (81) and tau_m = E_m / mu_s", "the corrected forms",
                    "a damaged moment matrix, a wrong invariant, a lost term, a sign and a rate of the wrong "
                    "dimension: none can have run (docs/guide/model.md)"});
  }
  return gaps;
}

SceneDefaults dissertation_scene_defaults(int dim, Shape shape) {
  SceneDefaults d = scene_defaults(PhysicsVersion::current, dim);
  d.a = dissertation_lattice_a(dim, shape);
  d.delta = ib::Delta::cosine;
  d.collision = lbm::CollisionModel::mrt;
  d.precision = lbm::Precision::double_precision;
  d.power_law_model = PowerLawModel::fluid_shell;
  d.marker_inset_rule = MarkerInsetRule::given;  // 0: the markers on the membrane
  return d;
}

double dissertation_radius(int dim, Shape shape) { return dim == 2 && shape == Shape::biconcave ? 0.5 : 1.0; }

double dissertation_lattice_a(int dim, Shape shape) {
  const double h = dim == 2 ? 0.05 : 0.1;  // Sec. 2
  return std::round(dissertation_radius(dim, shape) / h);
}

double dissertation_Re(int dim, Shape shape) { return 0.05 * dissertation_radius(dim, shape); }

std::vector<std::string> numerics_item_lines(int dim, Shape shape) {
  std::vector<std::string> lines;
  for (const auto& i : dissertation_numerics_items(dim, shape)) lines.push_back(i.key + " = " + i.value + ": " + i.source);
  return lines;
}

std::vector<std::string> numerics_gap_lines(int dim) {
  std::vector<std::string> lines;
  for (const auto& g : dissertation_numerics_gaps(dim)) lines.push_back(g.part + ": " + g.choice + " (" + g.why + ")");
  return lines;
}

}  // namespace capsule
