// The 3D member (Sec. 2.1, 2.3, 2.5): D3Q19 MRT fluid between moving walls, the triangulated
// FEM membrane with Helfrich bending and the volume penalty, coupled by the immersed
// boundary (17)-(21), optional viscosity contrast (15)-(16).
//
// Per lattice step (the same order as the 2D driver, simulation2d.cpp):
//   membrane forces at X(n) -> spread (21) -> fluid step with that force ->
//   interpolate u(n) at X(n) (19) -> X(n+1) = X(n) + U dt (20) -> viscosity field (if V != 1).
//   (resolution.membrane_update chooses the time level of U and the order of (20):
//   solver/ib/membrane_update.hpp.)
// The fluid starts in the linear Couette flow u = k (y - H/2) shear_factor(0); the walls move
// at -+ k H/2 shear_factor(kt).
//
// Conventions (solver/membrane3d/README.md "Conventions"):
//  - E_B = E_b a^2 E_s (a the markers' radius a - inset, see build_membrane). (35) prints
//    E_B/(a E_s), which has the dimension of a length; the text
//    works with a = 1, where both agree, and this form keeps the physics independent of the
//    resolution a (the same choice as the 2D driver). c0 is given in units of 1/a.
//  - Volume penalty (84): K_v = volume_penalty E_s / a (a pressure).
//  - Curvature: outward normal, kappa = 1/R > 0 on a sphere; c0 < 0 opposes it (bending.hpp).
//  - Series columns: see Simulation3D::row().
#include "solver/run/simulation3d.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "solver/ib/grid.hpp"
#include "solver/ib/interpolation.hpp"
#include "solver/ib/membrane_update.hpp"
#include "solver/ib/power_law_viscosity.hpp"
#include "solver/ib/spreading_box.hpp"
#include "solver/ib/support_rows.hpp"
#include "solver/ib/viscosity_contrast.hpp"
#include "solver/lbm/fluid.hpp"
#include "solver/lbm/refinement/refined_fluid.hpp"
#include <Eigen/Eigenvalues>

#include "solver/membrane3d/curvature.hpp"
#include "solver/membrane3d/membrane_forces.hpp"
#include "solver/membrane3d/optical_tweezers.hpp"
#include "solver/membrane3d/phase_angles.hpp"
#include "solver/membrane3d/shape_measures.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "solver/membrane3d/surface_geometry.hpp"
#include "solver/membrane3d/vtk_writer.hpp"
#include "solver/run/output_loop.hpp"
#include "solver/run/protocol.hpp"
#include "solver/scene/refined_block_extent.hpp"
#include "solver/scene/units.hpp"

namespace capsule {

namespace m3 = membrane3d;

namespace {

using Clock = std::chrono::steady_clock;

static_assert(sizeof(m3::Vec3) == 3 * sizeof(double), "membrane positions are used as a flat n x 3 array");



struct Timings {
  // Wall seconds: the fluid step; spreading, interpolation and the position update; the
  // viscosity field (contrast and power law, V != 1 or K > 0); its power-law part alone; the
  // clearing of the force field and spreading (21) alone (part of coupling).
  double fluid = 0, coupling = 0, power_law = 0, viscosity = 0, spreading = 0;
};

class Simulation3D {
 public:
  explicit Simulation3D(const Scene& s)
      : scene_(s), units_(units_for(s, choose_tau(s))), n_(s.grid()),
        grid_{n_[0], n_[1], n_[2]}, ib_grid_(grid_) {
    if (s.dim != 3) throw std::invalid_argument("Simulation3D: scene.dim must be 3");
    const double k = units_.shear_rate, H = grid_.ny;
    const double f0 = Protocol(s).shear_factor(0.0);
    if (s.resolution.refine) {
      make_refined_fluid();
    } else {
      fluid_ = std::make_unique<lbm::Fluid<lbm::D3Q19>>(n_[0], n_[1], n_[2], units_.nu, s.resolution.precision);
      fluid_->set_collision(s.resolution.collision);
      fluid_->initialise_velocity([&](double, double y, double) {
        return std::array<double, 3>{k * (y - 0.5 * H) * f0, 0.0, 0.0};  // linear Couette flow (1)
      });
    }
    build_membrane();
    U_.assign(3 * mesh_.vertex_count(), 0.0);
    // The viscosity field exists only for a contrast (V != 1) or a power-law membrane (K > 0).
    if (s.V != 1.0) contrast_ = std::make_unique<ib::ViscosityContrast<3>>(grid_, units_.nu, units_.nu_inside);
    if (s.power_law.K > 0 && s.power_law.model == PowerLawModel::fluid_shell) {
      power_law_ = std::make_unique<ib::PowerLawViscosity<3>>(
          grid_, delta_, ib::PowerLawParameters{s.power_law.K, s.power_law.n, units_.nu, s.resolution.a, units_.shear_rate});
      if (contrast_) base_nu_.assign(grid_.size(), units_.nu);
    }
    if (contrast_ || power_law_) update_viscosity();
    const auto d0 = m3::inertia_deformation(mesh_);
    phase_ = m3::PhaseTracker(mesh_, d0.centroid, d0.theta);
    area0_ = m3::surface_area(mesh_);
    start_angle_.resize(mesh_.vertex_count());
    for (int i = 0; i < mesh_.vertex_count(); ++i)
      start_angle_[i] = std::atan2(mesh_.x[i].y() - d0.centroid.y(), mesh_.x[i].x() - d0.centroid.x());
  }

  const Units& units() const { return units_; }
  double E_B() const { return E_B_; }
  double shear_modulus() const { return shear_modulus_; }
  double tau_m() const { return tau_m_; }
  double K_v() const { return K_v_; }
  const m3::Mesh& mesh() const { return mesh_; }
  // The fluid's steps: the lattice's, or the coarse lattice's under refinement (each two of the
  // fine lattice, where the membrane steps).
  long steps() const { return steps_; }
  long fine_steps() const { return refined_ ? 2 * steps_ : steps_; }
  // k per fluid step: the lattice's k, or twice the fine lattice's under refinement.
  double step_shear_rate() const { return refined_ ? 2.0 * units_.shear_rate : units_.shear_rate; }
  double kt() const { return steps_ * step_shear_rate(); }
  // Lattice node updates per fluid step (the progress line's MLUPS): every node, or the coarse
  // lattice's plus twice the fine lattice's under refinement.
  double node_updates_per_step() const {
    if (!refined_) return static_cast<double>(grid_.size());
    return static_cast<double>(refined_->block().coarse_size()) + 2.0 * static_cast<double>(refined_->block().fine_size());
  }
  const lbm::refinement::RefinedFluid<lbm::D3Q19>* refined_fluid() const { return refined_.get(); }
  const Timings& timings() const { return timings_; }
  const m3::MembraneTimings& membrane_timings() const { return forces_.timings(); }
  const std::vector<int>& tracked() const { return phase_.vertices(); }

  // What a snapshot shows on the membrane (output.snapshots, docs/guide/member-files.md
  // "Snapshots"): per vertex the membrane velocity (in units of k a), the mean curvature
  // (79) times a, and the angle it has turned about the centroid in the shear plane since the
  // start (the tank-treading phase of (91)-(92) at every vertex, in (-pi, pi]); per triangle the
  // principal stretches lambda_1 >= lambda_2 and the area dilation lambda_1 lambda_2 (the
  // invariants of C against the reference shape).
  std::vector<m3::VtkField> snapshot_point_fields() const {
    const std::size_t n = mesh_.vertex_count();
    const double velocity_unit = units_.shear_rate * scene_.resolution.a;
    m3::VtkField velocity{"membrane_velocity", 3, std::vector<double>(3 * n)};
    for (std::size_t i = 0; i < 3 * n; ++i) velocity.values[i] = U_[i] / velocity_unit;
    m3::VtkField curvature{"mean_curvature", 1, m3::fit_curvatures(mesh_).mean};
    for (double& k : curvature.values) k *= scene_.resolution.a;
    const m3::Vec3 c = m3::inertia_deformation(mesh_).centroid;
    m3::VtkField turn{"turned_angle", 1, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) {
      const double now = std::atan2(mesh_.x[i].y() - c.y(), mesh_.x[i].x() - c.x());
      turn.values[i] = std::remainder(now - start_angle_[i], 2 * M_PI);
    }
    return {velocity, curvature, turn};
  }
  std::vector<m3::VtkField> snapshot_cell_fields() const {
    const int t_count = mesh_.triangle_count();
    m3::VtkField l1{"stretch_1", 1, std::vector<double>(t_count)}, l2{"stretch_2", 1, std::vector<double>(t_count)},
        J{"area_dilation", 1, std::vector<double>(t_count)};
    for (int t = 0; t < t_count; ++t) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(forces_.elastic().cauchy_green(mesh_, t));
      const double s1 = std::sqrt(std::max(0.0, eig.eigenvalues()(1))), s2 = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
      l1.values[t] = s1, l2.values[t] = s2, J.values[t] = s1 * s2;
    }
    return {l1, l2, J};
  }

  void step(double shear_factor) {
    if (!broken_.empty() || !stopped_.empty()) return;  // the output loop reports it after this output interval
    if (refined_) return step_refined(shear_factor);
    const std::size_t n = mesh_.vertex_count();
    forces_.compute(mesh_, force_);
    if (load_on_) m3::add_pulling_forces(patches_, pull_force_, force_);  // the beads (stretch protocol)
    auto t0 = Clock::now();
    double* p[3] = {fluid_->force(0), fluid_->force(1), fluid_->force(2)};
    // The force field is zero except where the last step spread: clear only there, then spread
    // (21), both on all threads, bitwise the serial spreading (spreading_box.hpp).
    spreading_.clear_last_and_spread(grid_, positions(), reinterpret_cast<const double*>(force_.data()), n, p, delta_);
    timings_.spreading += std::chrono::duration<double>(Clock::now() - t0).count();
    const double wall = 0.5 * units_.shear_rate * grid_.ny * shear_factor;                  // k H / 2 (1)
    fluid_->set_wall_velocity(-wall, wall);
    const double* u[3] = {fluid_->velocity(0), fluid_->velocity(1), fluid_->velocity(2)};
    // previous_velocity: U^n(X^n), the fluid velocity of the time level of F(X^n) (membrane_update.hpp).
    if (update_ == ib::MembraneUpdate::previous_velocity) ib::interpolate<3>(grid_, u, positions(), n, U_.data(), delta_);
    set_macroscopic_region();
    auto t1 = Clock::now();
    fluid_->step();
    auto t2 = Clock::now();
    if (update_ != ib::MembraneUpdate::previous_velocity) ib::interpolate<3>(grid_, u, positions(), n, U_.data(), delta_);  // (19)
    if (update_ == ib::MembraneUpdate::adams_bashforth2) ib::advance_adams_bashforth2<3>(positions(), U_.data(), U_previous_, n, 1.0);
    else ib::advance<3>(positions(), U_.data(), n, 1.0);  // (20)
    check_positions();
    auto t3 = Clock::now();
    timings_.coupling += std::chrono::duration<double>((t1 - t0) + (t3 - t2)).count();
    timings_.fluid += std::chrono::duration<double>(t2 - t1).count();
    if (contrast_ || power_law_) {
      update_viscosity();
      timings_.viscosity += std::chrono::duration<double>(Clock::now() - t3).count();
    }
    ++steps_;
  }

  // Why step() stopped ("" while it runs): a vertex that is NaN or outside the channel would
  // index the lattice out of bounds in the next spreading.
  const std::string& failure() const { return broken_; }
  // Why step() stopped although the run is healthy ("" while it runs): the capsule's kernel
  // support reached the edge of the refined block.
  const std::string& stopped() const { return stopped_; }

  // Stretch protocol: whether the beads pull during the next steps (the output loop sets it).
  void set_load(bool on) { load_on_ = on; }
  const m3::PulledPatches& patches() const { return patches_; }
  double pull_force() const { return pull_force_; }

  // The next step writes u and rho everywhere (the output loop calls this before a row).
  void full_fields_next_step() { full_fields_next_ = true; }

  // One output row (docs/guide/member-files.md "3D series") and the phase angles (91)-(92) of the five tracked vertices.
  std::map<std::string, double> row(std::vector<double>& beta) {
    const auto d = m3::inertia_deformation(mesh_);
    beta = phase_.update(mesh_, d.centroid, d.theta);
    const double a = scene_.resolution.a;
    double umax2 = 0;
    if (refined_) umax2 = refined_->max_speed() * refined_->max_speed();
    else
      for (std::size_t i = 0; i < grid_.size(); ++i) {
        const double s = fluid_->velocity(0)[i] * fluid_->velocity(0)[i] + fluid_->velocity(1)[i] * fluid_->velocity(1)[i] +
                         fluid_->velocity(2)[i] * fluid_->velocity(2)[i];
        umax2 = std::max(umax2, s);
      }
    std::map<std::string, double> r = {
        {"kt", kt()},
        {"D_xy", d.D},                                              // inertia ellipsoid (38)
        {"D_extent", m3::extent_deformation(mesh_, d.centroid)},   // (r_max - r_min)/(r_max + r_min)
        {"theta", d.theta},
        {"L", d.L / a},
        {"W", d.W / a},
        {"volume_drift", m3::enclosed_volume(mesh_) / forces_.volume0() - 1.0},
        {"surface_drift", m3::surface_area(mesh_) / area0_ - 1.0},
        {"triangle_quality_min", m3::min_triangle_quality(mesh_)},
        {"inverted_triangles", static_cast<double>(inverted_triangles())},
        {"elastic_energy", forces_.elastic().energy(mesh_) / (units_.E_s * a * a)},
        {"centroid_x", (d.centroid.x() - 0.5 * grid_.nx) / a},
        {"centroid_y", (d.centroid.y() - 0.5 * grid_.ny) / a},
        {"centroid_z", (d.centroid.z() - 0.5 * grid_.nz) / a},
        {"max_speed", std::sqrt(umax2)},
    };
    if (scene_.power_law.K > 0) std::tie(r["gamma_min"], r["gamma_max"]) = gamma_range();
    if (scene_.protocol.stretch) {
      // In units of the membrane's radius r_m (StretchLoad), and in um for a physical cell.
      const m3::StretchDiameters sd = m3::stretch_diameters(mesh_);
      const double r_m = scene_.resolution.a - scene_.resolution.marker_inset;
      r["D_axial"] = sd.axial / r_m;
      r["D_transverse"] = sd.transverse / r_m;
      if (scene_.physical) {
        r["D_axial_um"] = r["D_axial"] * scene_.physical->radius_um;
        r["D_transverse_um"] = r["D_transverse"] * scene_.physical->radius_um;
      }
    }
    return r;
  }

  // "" when healthy, else the reason.
  std::string health(const std::map<std::string, double>& r) const {
    for (const auto& [k, v] : r)
      if (!std::isfinite(v)) return "NaN in " + k;
    for (const auto& x : mesh_.x)
      if (!x.allFinite()) return "NaN in membrane positions";
    std::ostringstream why;
    if (r.at("inverted_triangles") > 0) why << r.at("inverted_triangles") << " inverted triangles";
    else if (std::abs(r.at("volume_drift")) > max_volume_drift) why << "volume drift " << r.at("volume_drift") << " (bound " << max_volume_drift << ")";
    else if (r.at("triangle_quality_min") < min_quality) why << "triangle quality " << r.at("triangle_quality_min") << " (bound " << min_quality << ")";
    else if (r.at("max_speed") > max_speed) why << "fluid speed " << r.at("max_speed") << " (bound " << max_speed << ")";
    return why.str();
  }

  // Restart points (solver/run/checkpoint.hpp): everything a later step() and row() read.
  void save_state(io::StateArchive& a) const {
    if (refined_) {
      lbm::refinement::RefinedFluid<lbm::D3Q19>::State f;
      refined_->export_state(f);
      a.put("refined.coarse_populations", std::move(f.coarse));
      a.put("refined.fine_populations", std::move(f.fine));
      a.put("refined.coarse_density", std::move(f.coarse_density));
      a.put("refined.coarse_velocity", std::move(f.coarse_velocity));
      a.put("refined.fine_velocity", std::move(f.fine_velocity));
    } else {
      lbm::Fluid<lbm::D3Q19>::State f;
      fluid_->export_state(f);
      a.put("fluid.populations", std::move(f.populations));
      a.put("fluid.density", std::move(f.density));
      a.put("fluid.velocity", std::move(f.velocity));
      a.put("fluid.viscosity", std::move(f.viscosity));
    }
    a.put("membrane.x", shape());
    a.put("membrane.sls_memory", forces_.elastic().memory());
    a.put_integer("membrane.sls_started", forces_.elastic().memory_started() ? 1 : 0);
    // The reference state, to check that a resumed run rebuilt the same one.
    std::vector<double> reference(mesh_.triangle_count());
    for (int t = 0; t < mesh_.triangle_count(); ++t) reference[t] = forces_.elastic().reference_area(t);
    reference.push_back(forces_.volume0());
    a.put("membrane.reference", std::move(reference));
    a.put("sim.phase", phase_.continuous_positions());
    a.put_integer("sim.steps", steps_);
    if (update_ == ib::MembraneUpdate::adams_bashforth2) a.put("sim.U_previous", U_previous_);
    const auto& mt = forces_.timings();
    a.put("sim.seconds", std::vector<double>{timings_.fluid, timings_.coupling, timings_.power_law, mt.elastic_s,
                                             mt.curvature_s, mt.bending_s, timings_.viscosity});
    if (contrast_) {
      std::vector<std::int64_t> inside;
      const auto& flags = contrast_->inside_flags();
      for (std::size_t node = 0; node < flags.size(); ++node)
        if (flags[node]) inside.push_back(static_cast<std::int64_t>(node));
      a.put("contrast.inside", std::move(inside));
      const auto& band = contrast_->band_nodes();
      a.put("contrast.band", std::vector<std::int64_t>(band.begin(), band.end()));
      a.put_integer("contrast.initialised", contrast_->initialised() ? 1 : 0);
      a.put("contrast.base_nu", base_nu_);
    }
  }

  void restore_state(io::StateArchive& a) {
    std::vector<double> reference(mesh_.triangle_count());
    for (int t = 0; t < mesh_.triangle_count(); ++t) reference[t] = forces_.elastic().reference_area(t);
    reference.push_back(forces_.volume0());
    const auto& saved = a.doubles("membrane.reference");
    if (saved.size() != reference.size() || !std::equal(saved.begin(), saved.end(), reference.begin()))
      throw std::runtime_error("restart point: the membrane's reference state differs from this build's");
    if (refined_) {
      lbm::refinement::RefinedFluid<lbm::D3Q19>::State f{a.take_doubles("refined.coarse_populations"), a.take_doubles("refined.fine_populations"),
                                                         a.take_doubles("refined.coarse_density"), a.take_doubles("refined.coarse_velocity"),
                                                         a.take_doubles("refined.fine_velocity")};
      refined_->import_state(std::move(f));
    } else {
      lbm::Fluid<lbm::D3Q19>::State f{a.take_doubles("fluid.populations"), a.take_doubles("fluid.density"),
                                      a.take_doubles("fluid.velocity"), a.take_doubles("fluid.viscosity")};
      fluid_->import_state(std::move(f));
    }
    const auto& x = a.doubles("membrane.x");
    if (x.size() != 3 * mesh_.x.size()) throw std::runtime_error("restart point: membrane.x does not fit the mesh");
    for (std::size_t v = 0; v < mesh_.x.size(); ++v) mesh_.x[v] = m3::Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
    forces_.elastic().restore_memory(a.doubles("membrane.sls_memory"), a.integer("membrane.sls_started") != 0);
    phase_.restore(a.doubles("sim.phase"));
    steps_ = static_cast<long>(a.integer("sim.steps"));
    if (update_ == ib::MembraneUpdate::adams_bashforth2) U_previous_ = a.doubles("sim.U_previous");
    const auto& t = a.doubles("sim.seconds");
    if (t.size() >= 6) {  // 6: a restart point from before the viscosity column
      timings_ = {t[0], t[1], t[2], t.size() >= 7 ? t[6] : 0.0};
      forces_.set_timings({t[3], t[4], t[5]});
    }
    if (contrast_) {
      std::vector<char> inside(grid_.size(), 0);
      for (auto node : a.ints("contrast.inside")) inside.at(static_cast<std::size_t>(node)) = 1;
      const auto& band = a.ints("contrast.band");
      contrast_->restore(inside, std::vector<std::size_t>(band.begin(), band.end()), a.integer("contrast.initialised") != 0);
      base_nu_ = a.doubles("contrast.base_nu");
    }
    if (power_law_) {
      // Its support and field follow from the restored positions and velocity alone: rebuild
      // them (the fluid's viscosity already holds the field's contribution).
      const auto normals = m3::averaged_vertex_normals(mesh_);
      const auto areas = m3::voronoi_areas(mesh_);
      const double* u[3] = {fluid_->velocity(0), fluid_->velocity(1), fluid_->velocity(2)};
      power_law_->update(positions(), reinterpret_cast<const double*>(normals.data()), areas.data(),
                         mesh_.vertex_count(), u);
    }
    spreading_.forget();  // the next step clears the whole force field, then spreads
  }

  std::vector<double> shape() const {
    std::vector<double> xyz;
    xyz.reserve(3 * mesh_.vertex_count());
    for (const auto& p : mesh_.x) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    return xyz;
  }

  // Health bounds (docs/guide/member-files.md "Health checks"): the enclosed volume drifting by more than 5 % (the IB
  // leaks a fraction of a percent per unit kt at a = 10), a triangle degenerating below
  // quality 0.05 (icosphere: 0.97), a lattice speed above 0.2 (Mach 0.35).
  static constexpr double max_volume_drift = 0.05;
  static constexpr double min_quality = 0.05;
  static constexpr double max_speed = 0.2;

 private:
  double* positions() { return reinterpret_cast<double*>(mesh_.x.data()); }

  // Stops the member (failure()) at the first vertex that is NaN, beyond a wall, or absurdly far
  // along the periodic directions: a blow-up between two outputs.
  void check_positions() {
    if (const long v = ib::first_marker_outside<3>(grid_, positions(), mesh_.vertex_count()); v >= 0) {
      std::ostringstream why;
      why << "membrane vertex " << v << " left the fluid (NaN or beyond a wall) at step " << steps_ + 1;
      broken_ = why.str();
      return;
    }
    if (refined_) check_inside_block();
  }

  // Refinement: the fluid of the membrane's time step is the fine lattice's block; a vertex
  // whose delta would touch a ghost cell (never collided, so its force is lost and its velocity
  // stale) stops the member. Node i (centre i + 1/2) is touched from x when |i + 1/2 - x| < w/2:
  // the block's cells 2 .. nf - 3 hold the support for x in [3/2 + w/2, nf - 3/2 - w/2].
  void check_inside_block() {
    const auto& b = refined_->block();
    const double half = 0.5 * ib::delta_width(delta_);
    static const char* axis[3] = {"x", "y", "z"};
    for (int v = 0; v < mesh_.vertex_count(); ++v)
      for (int d = 0; d < 3; ++d) {
        if (b.spans(d)) continue;
        const double x = mesh_.x[v][d] + shift_[d];
        if (x < 1.5 + half || x > b.fine_n(d) - 1.5 - half) {
          std::ostringstream why;
          why << "the capsule left the refined block: membrane vertex " << v << "'s kernel reached the block's edge along "
              << axis[d] << " (resolution.refine.margin " << scene_.resolution.refine->margin
              << " a is too small for this deformation)";
          stopped_ = why.str();
          return;
        }
      }
  }

  // The positions in the fine lattice's frame (RefinedFluid::fine_grid): the domain's fine
  // spacings shifted by the block's origin.
  const double* block_frame_positions() {
    const std::size_t n = mesh_.vertex_count();
    local_.resize(3 * n);
    for (std::size_t v = 0; v < n; ++v)
      for (int d = 0; d < 3; ++d) local_[3 * v + d] = mesh_.x[v][d] + shift_[d];
    return local_.data();
  }

  // The refined fluid (resolution.refine, docs/guide/refinement.md "In a scene"): the scene's
  // lattice is the fine one (a, tau, k and the membrane in its units); the coarse lattice has
  // half the nodes per axis, half the lattice viscosity and the same lattice velocity.
  void make_refined_fluid() {
    const Scene& s = scene_;
    const RefinedBlockPlan plan = refined_block_extent(s);
    if (!plan.why.empty()) throw std::invalid_argument("resolution.refine: " + plan.why);
    const double tau_coarse = 0.5 + 0.5 * (units_.tau - 0.5);
    if (tau_coarse < 0.505)
      throw std::invalid_argument("resolution.refine: the coarse lattice's relaxation time " + std::to_string(tau_coarse) +
                                  " (the fine lattice's " + std::to_string(units_.tau) + ") is below 0.505: give a larger resolution.tau");
    refined_ = std::make_unique<lbm::refinement::RefinedFluid<lbm::D3Q19>>(n_[0] / 2, n_[1] / 2, n_[2] / 2, 0.5 * units_.nu, plan.extent,
                                                                             s.resolution.precision);
    refined_->set_collision(s.resolution.collision);
    const double k = units_.shear_rate, H = grid_.ny, f0 = Protocol(s).shear_factor(0.0);
    refined_->initialise_velocity([&](double, double y, double) {  // coarse spacings: y_fine = 2 y
      return std::array<double, 3>{k * (2.0 * y - 0.5 * H) * f0, 0.0, 0.0};  // linear Couette flow (1)
    });
    const auto g = refined_->fine_grid();
    ib_grid_ = ib::Grid{g[0], g[1], g[2]};
    for (int d = 0; d < 3; ++d) shift_[d] = refined_->to_fine(d, 0.0);
  }

  // One coarse step of the refined fluid: two membrane steps of the fine lattice's dt, each
  // spreading before a fine sub-step and moving the membrane after it (RefinedFluid::step), in
  // the order of step() above.
  void step_refined(double shear_factor) {
    const std::size_t n = mesh_.vertex_count();
    const double wall = 0.5 * units_.shear_rate * grid_.ny * shear_factor;  // k H / 2 (1): the same lattice velocity on both levels
    refined_->set_wall_velocity(-wall, wall);
    // The coarse lattice carries no force; its velocity is read only on the step before an
    // output row (max_speed), and its density only at the walls (which the fluid always writes).
    refined_->set_coarse_fields(full_fields_next_);
    full_fields_next_ = false;
    double* p[3] = {refined_->fine_force(0), refined_->fine_force(1), refined_->fine_force(2)};
    const double* u[3] = {refined_->fine_velocity(0), refined_->fine_velocity(1), refined_->fine_velocity(2)};
    const auto start = Clock::now();
    double hooks = 0;  // seconds in the membrane and coupling, the rest is the fluid's
    refined_->step(
        [&](int) {
          if (!broken_.empty() || !stopped_.empty()) return;
          const auto c0 = Clock::now();
          forces_.compute(mesh_, force_);
          if (load_on_) m3::add_pulling_forces(patches_, pull_force_, force_);
          const auto t0 = Clock::now();
          const double* X = block_frame_positions();
          spreading_.clear_last_and_spread(ib_grid_, X, reinterpret_cast<const double*>(force_.data()), n, p, delta_);
          const auto t1 = Clock::now();
          timings_.spreading += std::chrono::duration<double>(t1 - t0).count();
          if (update_ == ib::MembraneUpdate::previous_velocity) ib::interpolate<3>(ib_grid_, u, X, n, U_.data(), delta_);
          const auto t2 = Clock::now();
          timings_.coupling += std::chrono::duration<double>(t2 - t0).count();
          hooks += std::chrono::duration<double>(t2 - c0).count();
        },
        [&](int) {
          if (!broken_.empty() || !stopped_.empty()) return;
          const auto t0 = Clock::now();
          if (update_ != ib::MembraneUpdate::previous_velocity) ib::interpolate<3>(ib_grid_, u, local_.data(), n, U_.data(), delta_);  // (19)
          if (update_ == ib::MembraneUpdate::adams_bashforth2) ib::advance_adams_bashforth2<3>(positions(), U_.data(), U_previous_, n, 1.0);
          else ib::advance<3>(positions(), U_.data(), n, 1.0);  // (20)
          check_positions();
          const double dt = std::chrono::duration<double>(Clock::now() - t0).count();
          timings_.coupling += dt;
          hooks += dt;
        });
    timings_.fluid += std::chrono::duration<double>(Clock::now() - start).count() - hooks;
    ++steps_;
  }

  // The fluid writes u, rho and reads the force only on the rows (y, z) the membrane can
  // reach this step (Fluid::set_macroscopic_region, ib::support_rows): the bounding box of
  // X(n) widened by kRegionMargin nodes = 3 (the width-4 delta: spreading and interpolation at
  // X(n)) + 1 (centred-difference gradients of the power law, at X(n+1)) + 1 (X(n+1) - X(n)
  // < max_speed = 0.2). Everywhere on the step before an output row (max_speed reads it all).
  static constexpr int kRegionMargin = 5;
  void set_macroscopic_region() {
    if (refined_) return;  // the refined fluid's coarse fields: step_refined
    if (full_fields_next_) {
      fluid_->set_macroscopic_everywhere();
      full_fields_next_ = false;
      return;
    }
    const ib::RowRange r = ib::support_rows(grid_, positions(), mesh_.vertex_count(), kRegionMargin);
    fluid_->set_macroscopic_region({{r.y_begin, r.y_end, r.z_begin, r.z_end}});
  }

  void build_membrane() {
    const Scene& s = scene_;
    const double a = s.resolution.a;
    // Marker inset (scene resolution.marker_inset): the markers, and the reference shape, on the
    // radius r_m = a - inset, the moduli unchanged; the smeared shell acts as a surface about
    // half a lattice unit outside its markers (capsule rigid-sphere), so the capsule the flow
    // sees is then about the radius a. c0 is a curvature of the shape: c0 / r_m.
    const double r_m = a - s.resolution.marker_inset;
    const m3::Mesh unit = m3::unit_icosphere(s.resolution.mesh_level);
    const m3::Vec3 centre(0.5 * grid_.nx, 0.5 * grid_.ny, 0.5 * grid_.nz);
    // 45 degrees in the xy-plane (Sec. 2.5); a stretched cell lies with its disc in the xz-plane,
    // so that the pull along x is in the disc's plane, as the beads pull in the experiment.
    const double incline = s.protocol.stretch ? 0.0 : 0.25 * std::numbers::pi;
    if (s.shape == Shape::sphere) mesh_ = m3::sphere_mesh(unit, r_m);
    else if (s.shape == Shape::biconcave) mesh_ = m3::biconcave_mesh(unit, r_m);
    else throw std::invalid_argument("3D shape must be sphere or biconcave, got '" + choice_name(s.shape) + "'");
    // Table 1, case C: the stress-free reference is the sphere with the start shape's area.
    m3::Mesh reference = mesh_;
    if (s.reference_case == ReferenceCase::C) reference = m3::sphere_mesh(unit, std::sqrt(m3::surface_area(mesh_) / (4.0 * std::numbers::pi)));
    m3::rotate_about_z_and_translate(mesh_, incline, centre);
    m3::rotate_about_z_and_translate(reference, incline, centre);

    m3::MembraneParameters p;
    delta_ = s.resolution.delta;
    update_ = s.resolution.membrane_update;
    shear_modulus_ = shear_modulus_3d(s, units_);
    p.law = m3::Constitutive{elastic_law_3d(s.law), shear_modulus_, s.C};
    // The Maxwell element (solver/scene/units.hpp): the SLS (63)-(67), E_m = G E_s, tau_m = mu_s /
    // E_m (docs/conventions.md "Membrane viscosity in 3D"), mu_s = eta a mu_a (36); or the power law
    // in the membrane (scene power_law.model): the same element with the surface viscosity (102)
    // mu_s(gamma) = K a mu_a (gamma / k)^(n - 1) per triangle, so its Kelvin-Voigt limit is the
    // power-law membrane and n = 1 is eta = K (physical reading). The Kelvin-Voigt limit of the
    // SLS has surface viscosity E_m tau_m = mu_s ("physical"); the text's (63) read literally has a
    // Maxwell modulus g_1(0)/2 = E_m/3 and tau_m = mu_s / E_m with E_m = G E_s = 3 G (E_s/3): its
    // limit is mu_s/3 ("dissertation", SceneConventions::sls_viscosity).
    if (s.eta > 0 && !(s.G > 0)) throw std::invalid_argument("eta > 0 needs G = E_m/E_s > 0");
    const MaxwellElement3d maxwell = maxwell_element_3d(s, units_);
    if (maxwell.present) {
      tau_m_ = maxwell.tau_m;
      p.maxwell = maxwell.power_law
                      ? m3::MaxwellElement{maxwell.E_m, tau_m_, 1.0, m3::PowerLawRelaxation{true, s.power_law.n, units_.shear_rate}}
                      : m3::MaxwellElement{maxwell.E_m, tau_m_, 1.0};
      p.maxwell.skalak_area_term = s.physics_version == PhysicsVersion::v5;  // the law as it was
    }
    // E_b is the bending number of the sphere the membrane is: with the markers on r_m = a -
    // inset, E_B = E_b r_m^2 E_s, so bending stands to the shear elasticity (E_B / (E_s r_m^2))
    // as on a membrane of radius a (the flow's radius sets Ca; the elastic response needs no such
    // factor: its strain does not carry a length, docs/findings/immersed_boundary_error_budget.md).
    E_B_ = membrane_bending_modulus(s, units_);
    p.E_B = E_B_;
    if (s.reference_case == ReferenceCase::B) {
      // c0 = 2 kappa of the start shape, node by node (Table 1, case B).
      const m3::Curvatures k = m3::fit_curvatures(mesh_);
      p.c0.resize(mesh_.vertex_count());
      for (int v = 0; v < mesh_.vertex_count(); ++v) p.c0[v] = 2.0 * k.mean[v];
    } else {
      p.c0.assign(mesh_.vertex_count(), s.c0 / r_m);
    }
    K_v_ = s.volume_penalty * units_.E_s / a;
    p.K_v = K_v_;
    if (s.protocol.stretch) {
      // The beads' patches on the start shape, and F = force E_s r_m in lattice units (StretchLoad).
      patches_ = s.protocol.stretch->contact_diameter > 0 ? m3::patches_by_contact_diameter(mesh_, s.protocol.stretch->contact_diameter * r_m)
                                                 : m3::patches_by_fraction(mesh_, s.protocol.stretch->patch_fraction);
      pull_force_ = s.protocol.stretch->force * units_.E_s * r_m;
    }
    forces_ = m3::MembraneForces(reference, mesh_, std::move(p));
  }

  // The local viscosity (104): the fluid's own (mu_a, or the contrast (16) near the membrane)
  // plus the spread power-law membrane viscosity (103). rho = 1, so nu = mu.
  void update_viscosity() {
    const auto normals = m3::averaged_vertex_normals(mesh_);
    const double* nrm = reinterpret_cast<const double*>(normals.data());
    const std::size_t n = mesh_.vertex_count();
    if (power_law_) {
      const auto t0 = Clock::now();
      const auto areas = m3::voronoi_areas(mesh_);
      const double* u[3] = {fluid_->velocity(0), fluid_->velocity(1), fluid_->velocity(2)};
      power_law_->update(positions(), nrm, areas.data(), n, u);  // (99)-(103)
      timings_.power_law += std::chrono::duration<double>(Clock::now() - t0).count();
    }
    auto added = [&](std::size_t node) { return power_law_ ? power_law_->field(node) : 0.0; };
    if (contrast_)
      contrast_->update(positions(), nrm, n, [&](std::size_t node, double nu) {
        if (power_law_) base_nu_[node] = nu;
        fluid_->set_viscosity(node, nu + added(node));
      });
    if (power_law_) {
      auto base = [&](std::size_t node) { return contrast_ ? base_nu_[node] : units_.nu; };
      for (std::size_t node : power_law_->previously_touched()) fluid_->set_viscosity(node, base(node) + added(node));
      for (std::size_t node : power_law_->touched()) fluid_->set_viscosity(node, base(node) + added(node));
    }
  }

  // Surface shear rate (101), in units of k (power law only): over the membrane nodes with the
  // fluid shell (the lattice gradient (99)-(100)), over the triangles in the membrane reading
  // (their own motion over the last step; 0 before the first).
  std::pair<double, double> gamma_range() const {
    if (!power_law_) {
      const auto& g = forces_.elastic().surface_shear_rates();
      if (g.empty()) return {0.0, 0.0};
      const auto [lo, hi] = std::minmax_element(g.begin(), g.end());
      return {*lo, *hi};
    }
    const auto& g = power_law_->gamma();
    const auto [lo, hi] = std::minmax_element(g.begin(), g.end());
    return {*lo / units_.shear_rate, *hi / units_.shear_rate};
  }

  // Triangles whose normal opposes the averaged normal of their own vertices.
  int inverted_triangles() const {
    const auto vn = m3::averaged_vertex_normals(mesh_);
    int bad = 0;
    for (int t = 0; t < mesh_.triangle_count(); ++t) {
      const auto& tri = mesh_.triangles[t];
      if (m3::triangle_area_vector(mesh_, t).dot(vn[tri[0]] + vn[tri[1]] + vn[tri[2]]) <= 0) ++bad;
    }
    return bad;
  }

  Scene scene_;
  Units units_;
  std::vector<int> n_;
  ib::Grid grid_;     // the domain's lattice (the fine one under refinement): walls, centre, measures
  ib::Grid ib_grid_;  // the lattice the membrane spreads to and reads from: grid_, or the refined block's fine lattice
  std::string broken_;   // failure()
  std::string stopped_;  // stopped()
  std::unique_ptr<lbm::Fluid<lbm::D3Q19>> fluid_;                          // the uniform lattice, or
  std::unique_ptr<lbm::refinement::RefinedFluid<lbm::D3Q19>> refined_;     // resolution.refine
  std::array<double, 3> shift_{0.0, 0.0, 0.0};  // domain -> block frame (fine spacings)
  std::vector<double> local_;                     // positions in the block frame
  m3::Mesh mesh_;
  m3::MembraneForces forces_;
  std::vector<m3::Vec3> force_;
  std::unique_ptr<ib::ViscosityContrast<3>> contrast_;
  std::unique_ptr<ib::PowerLawViscosity<3>> power_law_;
  std::vector<double> base_nu_;  // the contrast viscosity (16) per node, kept when both act
  std::vector<double> U_;
  std::vector<double> start_angle_;  // each vertex's angle about the start centroid in the shear plane
  ib::SpreadingBox spreading_;       // (21); knows the box the last step spread to
  m3::PhaseTracker phase_;
  double E_B_ = 0, K_v_ = 0, area0_ = 0, shear_modulus_ = 0, tau_m_ = 0;
  // IB delta (scene resolution.kernel, solver/ib/delta.hpp), the scene's.
  ib::Delta delta_ = ib::Delta::peskin4;
  // Time level and order of the position update (scene resolution.membrane_update,
  // solver/ib/membrane_update.hpp); U_previous_: the last step's U, adams_bashforth2 only.
  ib::MembraneUpdate update_ = ib::MembraneUpdate::euler;
  std::vector<double> U_previous_;
  long steps_ = 0;
  bool full_fields_next_ = false;
  m3::PulledPatches patches_;  // stretch protocol: the beads' vertices and shares
  double pull_force_ = 0;      // F in lattice units
  bool load_on_ = false;
  Timings timings_;
};

// Seconds of one part of a step: the difference of an accumulated timer over the measurement.
double per_step(double after, double before, long steps) { return steps > 0 ? (after - before) / double(steps) : 0.0; }

}  // namespace

std::string snapshot_base(const std::string& member_path) {
  std::string base = member_path;
  if (base.size() > 3 && base.substr(base.size() - 3) == ".h5") base.resize(base.size() - 3);
  return base;
}
std::string snapshot_path(const std::string& member_path, double kt) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_kt%08.3f.vtp", kt);
  return snapshot_base(member_path) + buf;
}

namespace {

// The stretch protocol's load and measures, for the member file.
void record_stretch(io::MemberWriter& out, const Scene& scene, const m3::PulledPatches& p, double F_lattice, int vertices) {
  const StretchLoad& load = *scene.protocol.stretch;
  out.set_attribute("protocol_measure", std::string("D_axial: the markers t_max ... D_inf and the steady and settled rules read the axial diameter"));
  out.set_attribute("stretch_force", load.force);
  out.set_attribute("stretch_force_convention", std::string("F / (E_s r_m): E_s of Ca (34), r_m = a - marker_inset the membrane's radius; the force on each bead"));
  out.set_attribute("stretch_force_lattice", F_lattice);
  if (scene.physical) {
    const double pN = load.force_pN > 0 ? load.force_pN : load.force * physical_groups(*scene.physical, scene.law, scene.conventions.sls_viscosity).E_s *
                                                              scene.physical->radius_um * 1e-6 * 1e12;
    out.set_attribute("stretch_force_pN", pN);
  }
  out.set_attribute("stretch_patch", load.contact_diameter > 0
                                         ? "vertices within " + std::to_string(load.contact_diameter / 2) + " r_m of each pole (contact diameter " +
                                               std::to_string(load.contact_diameter) + " r_m)"
                                         : "the " + std::to_string(load.patch_fraction) + " of the vertices nearest each pole");
  out.set_attribute("stretch_patch_vertices", static_cast<long>(p.plus.size()));
  out.set_attribute("stretch_patch_vertices_minus", static_cast<long>(p.minus.size()));
  out.set_attribute("stretch_patch_vertex_fraction", static_cast<double>(p.plus.size()) / vertices);
  const double r_m = scene.resolution.a - scene.resolution.marker_inset;
  out.set_attribute("stretch_patch_area", p.plus_area / (r_m * r_m));  // on the start shape, in units of r_m^2
  out.set_attribute("stretch_force_spread", std::string("each patch vertex carries F A_i / sum A (A_i its Voronoi area (83) on the start shape): a uniform traction over the patch"));
}

// The refined block (resolution.refine), for the member file.
void record_refinement(io::MemberWriter& out, const Scene& scene, const lbm::refinement::RefinedFluid<lbm::D3Q19>& f) {
  const auto& b = f.block();
  std::ostringstream block;
  static const char* axis[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) {
    if (d) block << ", ";
    block << axis[d] << " ";
    if (b.spans(d)) block << "spanned (" << b.coarse_n(d) << " coarse cells, periodic)";
    else block << "[" << b.begin(d) << ", " << b.end(d) << ") of " << b.coarse_n(d);
  }
  out.set_attribute("refine", std::string("one static block at half the spacing and time step (docs/guide/refinement.md); "
                                          "a, tau, the shear rate and steps_per_kt are the fine lattice's"));
  out.set_attribute("refine_levels", static_cast<long>(scene.resolution.refine->levels));
  out.set_attribute("refine_margin", scene.resolution.refine->margin);
  out.set_attribute("refine_block_coarse_cells", block.str());
  out.set_attribute("refine_coarse_lattice", std::to_string(b.coarse_n(0)) + " x " + std::to_string(b.coarse_n(1)) + " x " + std::to_string(b.coarse_n(2)));
  out.set_attribute("refine_fine_lattice", std::to_string(b.fine_n(0)) + " x " + std::to_string(b.fine_n(1)) + " x " + std::to_string(b.fine_n(2)) +
                                               " (the block plus a ghost layer one coarse cell thick)");
  out.set_attribute("refine_start_shape_radius", start_shape_radius(scene) / scene.resolution.a);
}

}  // namespace

StepSplit3D time_steps3d(const Scene& scene, long warmup_steps, long steps) {
  Simulation3D sim(scene);
  const double factor = Protocol(scene).shear_factor(0.0);
  for (long i = 0; i < warmup_steps; ++i) sim.step(factor);
  const Timings t0 = sim.timings();
  const m3::MembraneTimings m0 = sim.membrane_timings();
  using RefinedSeconds = lbm::refinement::RefinedFluid<lbm::D3Q19>::Seconds;
  const RefinedSeconds f0 = sim.refined_fluid() ? sim.refined_fluid()->seconds() : RefinedSeconds{};
  const auto start = Clock::now();
  for (long i = 0; i < steps; ++i) sim.step(factor);
  StepSplit3D r;
  r.steps = steps;
  r.total = steps > 0 ? std::chrono::duration<double>(Clock::now() - start).count() / double(steps) : 0.0;
  const Timings& t1 = sim.timings();
  const m3::MembraneTimings& m1 = sim.membrane_timings();
  r.fluid = per_step(t1.fluid, t0.fluid, steps);
  r.coupling = per_step(t1.coupling, t0.coupling, steps);
  r.spreading = per_step(t1.spreading, t0.spreading, steps);
  r.viscosity = per_step(t1.viscosity, t0.viscosity, steps);
  r.elastic = per_step(m1.elastic_s, m0.elastic_s, steps);
  r.curvature = per_step(m1.curvature_s, m0.curvature_s, steps);
  r.bending = per_step(m1.bending_s, m0.bending_s, steps);
  r.vertices = sim.mesh().vertex_count();
  r.nodes = sim.node_updates_per_step();
  if (const auto* refined = sim.refined_fluid()) {
    const RefinedSeconds& f1 = refined->seconds();
    r.refined = true;
    r.coarse = per_step(f1.coarse, f0.coarse, steps);
    r.fine = per_step(f1.fine, f0.fine, steps);
    r.transfers = per_step(f1.transfers, f0.transfers, steps);
  }
  return r;
}

std::string run_simulation3d(const Scene& scene, io::MemberWriter& out, const RunControl& control) {
  Simulation3D sim(scene);
  Protocol protocol(scene);
  const Units& u = sim.units();
  const m3::Mesh& mesh = sim.mesh();
  record_units(out, scene, u);
  out.set_attribute("shear_modulus", sim.shear_modulus());
  out.set_attribute("shear_modulus_convention", std::string("neo-hookean: G_s = E_s/3 (Ramanujan-Pozrikidis E_s); skalak: G_s = E_s"));
  out.set_attribute("E_B", sim.E_B());
  out.set_attribute("E_B_convention", std::string("E_B = E_b r_m^2 E_s, r_m = a - marker_inset (the membrane's radius); W_b = (E_B/2) int (2 kappa - c0)^2 dS"));
  out.set_attribute("K_v", sim.K_v());
  out.set_attribute("mesh_level", static_cast<long>(scene.resolution.mesh_level));
  out.set_attribute("vertices", static_cast<long>(mesh.vertex_count()));
  out.set_attribute("triangles", static_cast<long>(mesh.triangle_count()));
  out.set_attribute("law", choice_name(scene.law));
  out.set_attribute("C", scene.C);
  out.set_attribute("G", scene.G);
  out.set_attribute("reference_case", choice_name(scene.reference_case));
  const bool membrane_power_law = scene.power_law.K > 0 && scene.power_law.model == PowerLawModel::membrane;
  out.set_attribute("viscoelastic", scene.eta > 0 ? std::string("standard linear solid (63)-(67), tau_m = mu_s/E_m")
                                    : membrane_power_law ? std::string("standard linear solid (63)-(67), tau = mu_s(gamma)/E_m per triangle (power law (102))")
                                                         : std::string("none"));
  out.set_attribute("sls_viscosity", scene.conventions.sls_viscosity == SlsViscosity::dissertation
                                         ? std::string("dissertation: (63) read literally, Kelvin-Voigt limit mu_s/3 = eta a mu_a/3")
                                         : std::string("physical: Kelvin-Voigt limit mu_s = eta a mu_a"));
  if (scene.eta > 0 || membrane_power_law) out.set_attribute("tau_m", sim.tau_m());
  out.set_attribute("delta", scene.resolution.delta == ib::Delta::peskin4
                                 ? std::string("peskin4: Peskin 4-point (zero first moment), not the cosine (18): README")
                                 : choice_name(scene.resolution.delta));
  out.set_attribute("marker_inset", scene.resolution.marker_inset);
  out.set_attribute("marker_radius", scene.resolution.a - scene.resolution.marker_inset);
  out.set_attribute("marker_inset_rule", scene.resolution.marker_inset_rule == MarkerInsetRule::given
                                             ? choice_name(scene.resolution.marker_inset_rule)
                                             : choice_name(scene.resolution.marker_inset_rule) + ": r_m + d_S(r_m) = a, solver/ib/hydrodynamic_radius.hpp");
  if (membrane_power_law)
    out.set_attribute("power_law", std::string("membrane: mu_s = K a mu_a (gamma/k)^(n - 1) (102) per triangle, gamma = sqrt(2 tr D_s^2) (101) of the triangle's "
                                               "own surface rate of deformation over the last step, in units of k, floored at 0.01; the "
                                               "Maxwell element of the standard linear solid (63)-(67) with E_m = G E_s and tau = mu_s / E_m"));
  else if (scene.power_law.K > 0)
    out.set_attribute("power_law", std::string("mu_mem = K a mu_a (gamma/k)^(n - 1) (102), a surface viscosity like mu_s = eta a mu_a; gamma = sqrt(2 tr D^2) (101) of the "
                                               "surface rate of deformation (99)-(100), in units of k, floored at 0.01; spread "
                                               "with the Voronoi areas (103) and added to the fluid viscosity (104)"));
  out.set_attribute("beta_tracked", std::string("5 vertices near the shear plane through the centroid, Gamma(0) = 0, pi/8, pi/4, 3pi/8, pi/2; continuous modulo pi"));

  std::vector<int> triangles;
  for (const auto& t : mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  std::vector<std::pair<double, std::string>> snapshots;  // (kt, .vtp file) written so far
  if (const auto* refined = sim.refined_fluid()) record_refinement(out, scene, *refined);
  const std::string status = run_output_loop(
      sim, scene, protocol, out, control, sim.step_shear_rate(), sim.node_updates_per_step(),
      [&](std::vector<double>& beta) { return sim.row(beta); },
      [&](double kt) {
        out.add_shape(kt, sim.shape(), 3, triangles);
        if (scene.output.snapshots == Snapshots::vtk) {
          const std::string file = snapshot_path(out.final_path(), kt);
          // Points in units of a from the domain centre, as the series centroid_x/y/z.
          const m3::VtkFrame frame{0.5 * m3::Vec3(scene.grid()[0], scene.grid()[1], scene.grid()[2]), scene.resolution.a};
          m3::write_vtp(file, sim.mesh(), sim.snapshot_point_fields(), sim.snapshot_cell_fields(), frame);
          snapshots.emplace_back(kt, std::filesystem::path(file).filename().string());
          m3::write_pvd(snapshot_base(out.final_path()) + ".pvd", snapshots);  // a time series for ParaView
        }
      });
  if (scene.protocol.stretch) record_stretch(out, scene, sim.patches(), sim.pull_force(), mesh.vertex_count());
  out.set_markers(protocol.markers());
  out.set_attribute("protocol", protocol.phase_note());
  out.set_attribute("steps", sim.fine_steps());  // of the lattice of steps_per_kt (the fine one under refinement)
  out.set_attribute("seconds_fluid", sim.timings().fluid);
  out.set_attribute("seconds_coupling", sim.timings().coupling);
  out.set_attribute("seconds_power_law", sim.timings().power_law);
  out.set_attribute("seconds_viscosity", sim.timings().viscosity);
  out.set_attribute("seconds_membrane_elastic", sim.membrane_timings().elastic_s);
  out.set_attribute("seconds_membrane_curvature", sim.membrane_timings().curvature_s);
  out.set_attribute("seconds_membrane_bending", sim.membrane_timings().bending_s);
  return status;
}

}  // namespace capsule
