#include "solver/run/simulation2d.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "solver/ib/grid.hpp"
#include "solver/ib/interpolation.hpp"
#include "solver/ib/mobility.hpp"
#include "solver/ib/viscosity_contrast.hpp"
#include "solver/lbm/fluid.hpp"
#include "solver/membrane2d/measures.hpp"
#include "solver/membrane2d/membrane.hpp"
#include "solver/membrane2d/shape.hpp"
#include "solver/run/output_loop.hpp"
#include "solver/run/protocol.hpp"

namespace capsule {


namespace {
using Clock = std::chrono::steady_clock;
// Mobility of the implicit Kelvin-Voigt prediction (Membrane::set_node_velocity). A node force F
// reaches its own interpolated velocity over two steps: (3/8)^2 F / 2 = 0.0703 F in its own step
// (the F/2 of u (22); Peskin self weight sum phi^2 = (3/8)^2 in 2D) and 0.0797 F in the next
// (tests/solver/run: "IB self-mobility"; the text's cosine delta (18) has the same sum phi^2 at a
// node). The prediction uses 2 (3/8)^2: measured at a = 10 it keeps
// eta up to 20 stable (0.1406: 12 runs, 16 does not; 24 blows up with either); D_xy(kt) at eta = 12 is the
// same to 6 digits with 0.1406 and 0.2812, and steady states do not depend on it at all.
constexpr double kKVMobility = 2.0 * (3.0 / 8.0) * (3.0 / 8.0);
}  // namespace

struct Simulation2D::Impl {
  Scene scene;
  Units units;
  // resolution.kernel: Peskin's 4-point delta by default, not the cosine delta (18) (its first
  // moment is not zero: docs/guide/model.md "Immersed boundary kernel"); cosine under the
  // dissertation's numerics.
  ib::Delta delta;
  ib::Grid grid;
  lbm::Fluid<lbm::D2Q9> fluid;
  membrane2d::Membrane membrane;
  std::unique_ptr<ib::ViscosityContrast<2>> contrast;
  std::vector<double> U;
  std::vector<double> spread_from;  // node positions of the last spreading
  std::string broken;               // why step() stopped, if it did
  double area0 = 0;
  long steps = 0;
  membrane2d::PhaseAngle phase;
  double t_membrane = 0, t_fluid = 0;
  // resolution.kelvin_voigt_step = "exact_mobility": the step's IB mobility and force-free velocity
  bool exact_kv = false;
  ib::StepMobility2D mobility;

  static membrane2d::Membrane make_membrane(const Scene& s, const Units& u, const std::vector<int>& n) {
    const double cx = 0.5 * n[0], cy = 0.5 * n[1];
    const double incline = 0.25 * std::numbers::pi;  // 45 degrees (Sec. 2.4)
    // "dissertation": (24)-(25) with the printed a, i.e. equivalent radius 0.740 a (SceneConventions::biconcave_2d).
    // Marker inset (scene resolution.marker_inset, 0 by default in 2D): the nodes, and the reference
    // shape, on the radius r_m = a - inset, the moduli unchanged (as in 3D, simulation3d.cpp); the
    // smeared membrane then acts as a circle of radius about a. E_b is the bending number of the
    // circle the membrane is: E_B = E_b r_m^2 E_s.
    const double scale = (s.resolution.a - s.resolution.marker_inset) / s.resolution.a;
    const double r_eq = scale * (s.conventions.biconcave_2d == BiconcaveSize2d::dissertation ? s.resolution.a * membrane2d::biconcave_equivalent_radius() : s.resolution.a);
    auto xy = s.shape == Shape::biconcave ? membrane2d::biconcave(s.resolution.segments, r_eq, cx, cy, incline)
                                     : membrane2d::circle(s.resolution.segments, scale * s.resolution.a, cx, cy, incline);
    return membrane2d::Membrane(std::move(xy), {u.E_s, membrane_bending_modulus(s, u), u.mu_s}, elastic_law_2d(s.law));
  }

  Impl(const Scene& s, const Units& u, const std::vector<int>& n)
      : scene(s), units(u), delta(s.resolution.delta), grid{n[0], n[1], 1}, fluid(n[0], n[1], 1, u.nu, s.resolution.precision),
        membrane(make_membrane(s, u, n)), exact_kv(s.resolution.kelvin_voigt_step == KelvinVoigtStep::exact_mobility) {
    U.assign(2 * membrane.size(), 0.0);
    area0 = membrane2d::polygon_area(membrane.positions());
    if (s.V != 1.0) {
      contrast = std::make_unique<ib::ViscosityContrast<2>>(grid, u.nu, u.nu_inside);
      update_contrast();
    }
  }

  void update_contrast() {
    const auto normals = membrane.outward_normals();
    contrast->update(membrane.positions().data(), normals.data(), membrane.size(),
                     [&](std::size_t node, double nu) { fluid.set_viscosity(node, nu); });
  }
};

Simulation2D::Simulation2D(const Scene& scene, bool start_in_shear) {
  if (scene.dim != 2) throw std::invalid_argument("Simulation2D: scene.dim must be 2");
  // Requested physics is never silently dropped: the power law (99)-(104) is built for the 3D membrane only.
  if (scene.power_law.K > 0)
    throw std::invalid_argument("power_law.K > 0: the power-law membrane viscosity (Sec. 5.2) is a 3D model; in 2D use eta (Kelvin-Voigt)");
  const Units u = units_for(scene, choose_tau(scene));
  impl_ = std::make_unique<Impl>(scene, u, scene.grid());
  // Initial linear Couette flow (1), scaled like the walls.
  const double k = u.shear_rate, H = impl_->grid.ny;
  const double f0 = start_in_shear ? Protocol(scene).shear_factor(0.0) : 0.0;
  impl_->fluid.initialise_velocity([&](double, double y, double) {
    return std::array<double, 3>{k * (y - 0.5 * H) * f0, 0.0, 0.0};
  });
}

Simulation2D::~Simulation2D() = default;

const Units& Simulation2D::units() const { return impl_->units; }
long Simulation2D::steps() const { return impl_->steps; }
double Simulation2D::kt() const { return impl_->steps * impl_->units.shear_rate; }
double Simulation2D::seconds_membrane() const { return impl_->t_membrane; }
double Simulation2D::seconds_fluid() const { return impl_->t_fluid; }
std::vector<double> Simulation2D::shape() const { return impl_->membrane.positions(); }
const std::string& Simulation2D::failure() const { return impl_->broken; }

void Simulation2D::set_shape(const std::vector<double>& xy) {
  if (xy.size() != impl_->membrane.positions().size()) throw std::invalid_argument("set_shape: wrong node count");
  impl_->membrane.positions() = xy;
  impl_->membrane.refit();
  if (impl_->contrast) impl_->update_contrast();
}

double Simulation2D::viscosity_at(double x, double y) const {
  const int i = ib::wrap(static_cast<int>(std::floor(x)), impl_->grid.nx);
  const int j = std::clamp(static_cast<int>(std::floor(y)), 0, impl_->grid.ny - 1);
  return impl_->fluid.viscosity(impl_->grid.index(i, j));
}

void Simulation2D::step(double shear_factor) {
  Impl& s = *impl_;
  if (!s.broken.empty()) return;  // the health check reports it at the next output
  const std::size_t n = s.membrane.size();
  auto t0 = Clock::now();
  if (s.units.mu_s > 0.0 && s.exact_kv) {
    // Kelvin-Voigt (31) with the velocities this step will really give the nodes, U = U_free + M F
    // (solver/ib/mobility.hpp, Membrane::compute_forces_coupled).
    s.mobility.assemble(s.grid, s.membrane.positions().data(), n, s.delta,
                        [&](std::size_t node) { return s.fluid.moments(node); });
    s.membrane.compute_forces_coupled(s.mobility.free_velocity(), s.mobility.matrix());
  } else {
    // Kelvin-Voigt (31) implicitly in the node velocities (Membrane::set_node_velocity): s.U moved
    // the nodes onto X(n) (zero before the first step: the membrane starts at rest).
    if (s.units.mu_s > 0.0) s.membrane.set_node_velocity(s.U, kKVMobility);
    s.membrane.compute_forces(1.0);  // dt = 1
  }
  double* p[2] = {s.fluid.force(0), s.fluid.force(1)};
  // the force field is zero except where the last step spread: clear only there
  if (s.spread_from.empty()) s.fluid.clear_force();
  else ib::clear_support<2>(s.grid, s.spread_from.data(), n, p, s.delta);
  s.spread_from = s.membrane.positions();
  ib::spread<2>(s.grid, s.membrane.positions().data(), s.membrane.forces().data(), n, p, s.delta);  // (21)
  const double wall = 0.5 * s.units.shear_rate * s.grid.ny * shear_factor;             // k H / 2 (1)
  s.fluid.set_wall_velocity(-wall, wall);
  auto t1 = Clock::now();
  s.fluid.step();
  auto t2 = Clock::now();
  const double* u[2] = {s.fluid.velocity(0), s.fluid.velocity(1)};
  ib::interpolate<2>(s.grid, u, s.membrane.positions().data(), n, s.U.data(), s.delta);  // (19)
  ib::advance<2>(s.membrane.positions().data(), s.U.data(), n, 1.0);            // (20)
  // Never index the lattice with a node that is NaN or outside the channel (a blow-up between
  // two outputs): stop moving and let health() end the member.
  if (const long c = ib::first_marker_outside<2>(s.grid, s.membrane.positions().data(), n); c >= 0) {
    std::ostringstream why;
    why << "membrane node " << c << " left the fluid (NaN or beyond a wall) at step " << s.steps + 1;
    s.broken = why.str();
  }
  if (s.contrast) s.update_contrast();
  auto t3 = Clock::now();
  s.t_membrane += std::chrono::duration<double>((t1 - t0) + (t3 - t2)).count();
  s.t_fluid += std::chrono::duration<double>(t2 - t1).count();
  ++s.steps;
}

namespace {
std::vector<std::int64_t> as_ints(const std::vector<std::size_t>& v) { return {v.begin(), v.end()}; }
void require_equal(const std::vector<double>& saved, const std::vector<double>& rebuilt, const char* what) {
  if (saved.size() != rebuilt.size() || !std::equal(saved.begin(), saved.end(), rebuilt.begin()))
    throw std::runtime_error(std::string("restart point: the ") + what + " differs from this build's");
}
}  // namespace

void Simulation2D::save_state(io::StateArchive& a) const {
  const Impl& s = *impl_;
  lbm::Fluid<lbm::D2Q9>::State f;
  s.fluid.export_state(f);
  a.put("fluid.populations", std::move(f.populations));
  a.put("fluid.density", std::move(f.density));
  a.put("fluid.velocity", std::move(f.velocity));
  a.put("fluid.viscosity", std::move(f.viscosity));
  const auto h = s.membrane.history();
  a.put("membrane.xy", h.xy);
  a.put("membrane.lambda_prev1", h.lambda_prev1);
  a.put("membrane.lambda_prev2", h.lambda_prev2);
  a.put("membrane.U", h.U);
  a.put("membrane.Fv_prev", h.Fv_prev);
  a.put("membrane.flags", std::vector<std::int64_t>{h.steps, h.implicit ? 1 : 0});
  a.put_number("membrane.mobility", h.mobility);
  // The reference state, to check that a resumed run rebuilt the same one.
  a.put("membrane.reference_lengths", s.membrane.reference_lengths());
  a.put("membrane.reference_curvature", s.membrane.reference_curvature());
  a.put("sim.U", s.U);
  a.put_integer("sim.steps", s.steps);
  a.put("sim.phase", s.phase.state());
  a.put("sim.seconds", std::vector<double>{s.t_membrane, s.t_fluid});
  if (s.contrast) {
    std::vector<std::int64_t> inside;
    const auto& flags = s.contrast->inside_flags();
    for (std::size_t node = 0; node < flags.size(); ++node)
      if (flags[node]) inside.push_back(static_cast<std::int64_t>(node));
    a.put("contrast.inside", std::move(inside));
    a.put("contrast.band", as_ints(s.contrast->band_nodes()));
    a.put_integer("contrast.initialised", s.contrast->initialised() ? 1 : 0);
  }
}

void Simulation2D::restore_state(io::StateArchive& a) {
  Impl& s = *impl_;
  require_equal(a.doubles("membrane.reference_lengths"), s.membrane.reference_lengths(), "membrane's reference lengths");
  require_equal(a.doubles("membrane.reference_curvature"), s.membrane.reference_curvature(), "membrane's reference curvature");
  lbm::Fluid<lbm::D2Q9>::State f{a.take_doubles("fluid.populations"), a.take_doubles("fluid.density"),
                                 a.take_doubles("fluid.velocity"), a.take_doubles("fluid.viscosity")};
  s.fluid.import_state(std::move(f));
  membrane2d::Membrane::History h;
  h.xy = a.doubles("membrane.xy");
  h.lambda_prev1 = a.doubles("membrane.lambda_prev1");
  h.lambda_prev2 = a.doubles("membrane.lambda_prev2");
  h.U = a.doubles("membrane.U");
  h.Fv_prev = a.doubles("membrane.Fv_prev");
  const auto& flags = a.ints("membrane.flags");
  if (flags.size() != 2) throw std::runtime_error("restart point: membrane.flags is not 2 integers");
  h.steps = static_cast<int>(flags[0]);
  h.implicit = flags[1] != 0;
  h.mobility = a.number("membrane.mobility");
  s.membrane.restore(h);
  s.U = a.doubles("sim.U");
  if (s.U.size() != 2 * s.membrane.size()) throw std::runtime_error("restart point: sim.U does not fit the membrane");
  s.steps = static_cast<long>(a.integer("sim.steps"));
  s.phase.restore(a.doubles("sim.phase"));
  const auto& t = a.doubles("sim.seconds");
  if (t.size() == 2) s.t_membrane = t[0], s.t_fluid = t[1];
  if (s.contrast) {
    std::vector<char> inside(s.grid.size(), 0);
    for (auto node : a.ints("contrast.inside")) inside.at(static_cast<std::size_t>(node)) = 1;
    const auto& band = a.ints("contrast.band");
    s.contrast->restore(inside, std::vector<std::size_t>(band.begin(), band.end()), a.integer("contrast.initialised") != 0);
  }
  s.spread_from.clear();  // the next step clears the whole force field, then spreads
  s.broken.clear();
}

std::map<std::string, double> Simulation2D::row() {
  Impl& s = *impl_;
  const auto& xy = s.membrane.positions();
  const auto td = membrane2d::taylor_deformation(xy);
  const double alpha = std::atan2(xy[1] - td.centroid.y, xy[0] - td.centroid.x);
  s.phase.observe(alpha, td.theta);
  // tensions and moments of the last force evaluation (this step's shape up to one step)
  const auto& tau = s.membrane.tension();
  const auto& m = s.membrane.bending_moment();
  const auto& lambda = s.membrane.stretch();
  const auto& l0 = s.membrane.reference_lengths();
  double L = 0, tau_sum = 0, m_sum = 0, lmin = std::numeric_limits<double>::infinity(), lmax = 0;
  for (std::size_t i = 0; i < s.membrane.size(); ++i) {
    const double li = l0[i] * lambda[i];
    L += li;
    tau_sum += tau[i] * li;
    m_sum += std::abs(m[i]) * li;
    lmin = std::min(lmin, lambda[i]);
    lmax = std::max(lmax, lambda[i]);
  }
  double umax = 0;
  for (std::size_t i = 0; i < s.grid.size(); ++i)
    umax = std::max(umax, std::hypot(s.fluid.velocity(0)[i], s.fluid.velocity(1)[i]));
  const double a = s.scene.resolution.a;
  return {
      {"kt", kt()},
      {"D_xy", td.D},
      {"theta", td.theta},
      {"L", td.L / a},
      {"W", td.W / a},
      {"area_drift", membrane2d::polygon_area(xy) / s.area0 - 1.0},
      {"tension", tau_sum / L / s.units.E_s},                // mean tau, units of E_s
      {"bending_moment", m_sum / L / (s.units.E_s * a)},   // mean |m|, units of E_s a
      {"stretch_min", lmin},
      {"stretch_max", lmax},
      {"centroid_x", (td.centroid.x - 0.5 * s.grid.nx) / a},
      {"centroid_y", (td.centroid.y - 0.5 * s.grid.ny) / a},
      {"max_speed", umax},
  };
}

double Simulation2D::beta() const {
  const double pi = std::numbers::pi;
  return std::remainder(impl_->phase.unwrapped(), 2.0 * pi);
}

std::string Simulation2D::health(const std::map<std::string, double>& r) const {
  if (!impl_->broken.empty()) return impl_->broken;
  for (const auto& [k, v] : r)
    if (!std::isfinite(v)) return "NaN in " + k;
  for (double x : impl_->membrane.positions())
    if (!std::isfinite(x)) return "NaN in membrane positions";
  std::ostringstream why;
  if (r.at("stretch_max") > max_stretch) why << "a segment stretched to " << r.at("stretch_max") << " (bound " << max_stretch << ")";
  else if (r.at("stretch_min") < min_stretch) why << "a segment compressed to " << r.at("stretch_min") << " (bound " << min_stretch << ")";
  else if (std::abs(r.at("area_drift")) > max_area_drift) why << "area drift " << r.at("area_drift") << " (bound " << max_area_drift << ")";
  else if (r.at("max_speed") > max_speed) why << "fluid speed " << r.at("max_speed") << " (bound " << max_speed << ")";
  return why.str();
}

std::string run_simulation2d(const Scene& scene, io::MemberWriter& out, const RunControl& control) {
  Simulation2D sim(scene);
  Protocol protocol(scene);
  const Units& u = sim.units();
  record_units(out, scene, u);
  if (scene.resolution.marker_inset != 0.0) {
    // The nodes on r_m = a - inset, bending that of the circle they form (make_membrane).
    const double r_m = scene.resolution.a - scene.resolution.marker_inset;
    out.set_attribute("marker_inset", scene.resolution.marker_inset);
    out.set_attribute("marker_radius", r_m);
    out.set_attribute("E_B", membrane_bending_modulus(scene, u));
    out.set_attribute("E_B_convention", std::string("E_B = E_b r_m^2 E_s, r_m = a - marker_inset (the membrane's radius)") +
                                            (scene.conventions.E_b_2d == BendingConvention2d::dissertation ? ", with the dissertation's 2D factor 2 (README Conventions)" : ""));
  }
  out.set_attribute("segments", static_cast<long>(scene.resolution.segments));
  out.set_attribute("delta", scene.resolution.delta == ib::Delta::cosine
                                 ? std::string("cosine: the text's (18) (first moment not zero: docs/guide/model.md)")
                                 : std::string("peskin4: Peskin 4-point (zero first moment), not the cosine (18): docs/guide/model.md"));
  out.set_attribute("beta_tracked", std::string("node 0, initially at the end of the major axis; wrapped into (-pi, pi]"));

  const std::string status = run_output_loop(
      sim, scene, protocol, out, control, u.shear_rate, static_cast<double>(scene.grid()[0]) * scene.grid()[1],
      [&](std::vector<double>& beta) {
        beta.assign(1, sim.beta());
        return sim.row();
      },
      [&](double kt) { out.add_shape(kt, sim.shape(), 2); });
  out.set_markers(protocol.markers());
  out.set_attribute("protocol", protocol.phase_note());
  out.set_attribute("steps", sim.steps());
  out.set_attribute("seconds_membrane_coupling", sim.seconds_membrane());
  out.set_attribute("seconds_fluid", sim.seconds_fluid());
  return status;
}

}  // namespace capsule
