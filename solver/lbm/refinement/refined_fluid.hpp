#pragma once
// The MRT lattice Boltzmann fluid of fluid.hpp with one static block refined by a factor 2
// (docs/guide/refinement.md). The coarse lattice fills the channel (walls at y = 0 and ny,
// moving in x, half-way bounce-back; periodic in x and z); the fine lattice holds the block at
// spacing dx/2 and time step dt/2 (acoustic scaling: the lattice velocity is the same on both,
// the lattice viscosity doubles, nu_f = 2 nu_c, i.e. tau_f - 1/2 = 2 (tau_c - 1/2)), plus a
// ghost layer over the ring of coarse cells around it (refined_block.hpp).
//
// One coarse step (recursive sub-cycling, Rohde et al. 2006 in the order waLBerla uses):
//   1. collide every coarse cell not covered by the block (collision.hpp, force (22)-(23));
//   2. explode the ring's post-collision populations into the fine ghost layer (explosion.hpp);
//   3. two fine sub-steps: collide the block cells with the fine force, stream the whole fine
//      lattice (ghost cells are streamed, never collided);
//   4. stream the coarse lattice; ring cells take the populations that come from the fine
//      lattice as children averages (coalescence.hpp).
// The mass of the populations, sum over uncovered coarse cells of 2^D sum_i f_i plus sum over
// block cells of sum_i f_i (in fine cell volumes), is conserved to round-off.
//
// Units: everything is in the lattice units of its own level. The coarse force and the coarse
// velocity are in coarse units; the fine force is in fine units (a body-force density F_c on the
// coarse lattice is F_c / 2 on the fine one), the fine velocity likewise (the same number as in
// coarse units). After step() the coarse velocity is that of coarse level n (fluid.hpp) and the
// fine velocity that of the second sub-step, fine level 2n + 1.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "solver/lbm/collision.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/refinement/coalescence.hpp"
#include "solver/lbm/refinement/explosion.hpp"
#include "solver/lbm/refinement/refined_block.hpp"
#include "solver/lbm/relaxation.hpp"

namespace capsule::lbm::refinement {

template <class L>
class RefinedFluid {
 public:
  static constexpr int Q = L::Q;
  static constexpr int D = L::D;
  using Block = RefinedBlock<D>;

  // nu: kinematic viscosity in coarse lattice units; starts at rest, rho = 1.
  RefinedFluid(int nx, int ny, int nz, double nu, const BlockExtent& extent)
      : block_(nx, ny, nz, extent),
        s_coarse_(shear_rate_from_viscosity(nu)),
        s_fine_(shear_rate_from_viscosity(2.0 * nu)),
        coarse_(block_.coarse_size() * Q),
        coarse_next_(coarse_.size()),
        fine_(block_.fine_size() * Q),
        fine_next_(fine_.size()),
        coarse_force_(3 * block_.coarse_size(), 0.0),
        fine_force_(3 * block_.fine_size(), 0.0),
        coarse_rho_(block_.coarse_size(), 1.0),
        coarse_u_(3 * block_.coarse_size(), 0.0),
        fine_u_(3 * block_.fine_size(), 0.0) {
    if (!(nu > 0.0)) throw std::invalid_argument("RefinedFluid: viscosity must be positive");
    for (int z = 0; z < block_.coarse_n(2); ++z)
      for (int y = 0; y < block_.coarse_n(1); ++y)
        for (int x = 0; x < block_.coarse_n(0); ++x)
          if (block_.ring({x, y, z})) ring_cells_.push_back(block_.coarse_index(x, y, z));
    moved_.assign(block_.coarse_size(), 0.0);
    initialise_velocity([](double, double, double) { return std::array<double, 3>{0.0, 0.0, 0.0}; });
  }

  const Block& block() const { return block_; }
  double shear_rate_coarse() const { return s_coarse_; }
  double shear_rate_fine() const { return s_fine_; }

  // The relaxation rates of both levels (relaxation.hpp): mrt, or trt with Lambda = 3/16.
  void set_collision(CollisionModel model) { collision_ = model; }

  void set_wall_velocity(double u_bottom, double u_top) {
    u_bottom_ = u_bottom;
    u_top_ = u_top;
  }

  // Equilibrium (5) at rho = 1 with velocity u(x, y, z), positions in coarse spacings, on both levels.
  void initialise_velocity(const std::function<std::array<double, 3>(double, double, double)>& u) {
    for (int z = 0; z < block_.coarse_n(2); ++z)
      for (int y = 0; y < block_.coarse_n(1); ++y)
        for (int x = 0; x < block_.coarse_n(0); ++x) {
          const std::size_t n = block_.coarse_index(x, y, z);
          const auto v = u(x + 0.5, y + 0.5, z + 0.5);
          equilibrium(1.0, v, &coarse_[n * Q]);
          for (int a = 0; a < 3; ++a) coarse_u_[a * block_.coarse_size() + n] = a < D ? v[a] : 0.0;
        }
    for (int z = 0; z < block_.fine_n(2); ++z)
      for (int y = 0; y < block_.fine_n(1); ++y)
        for (int x = 0; x < block_.fine_n(0); ++x) {
          const std::size_t n = block_.fine_index(x, y, z);
          const auto p = block_.fine_centre({x, y, z});
          const auto v = u(p[0], p[1], p[2]);
          equilibrium(1.0, v, &fine_[n * Q]);
          for (int a = 0; a < 3; ++a) fine_u_[a * block_.fine_size() + n] = a < D ? v[a] : 0.0;
        }
  }

  double* coarse_force(int a) { return coarse_force_.data() + std::size_t(a) * block_.coarse_size(); }
  double* fine_force(int a) { return fine_force_.data() + std::size_t(a) * block_.fine_size(); }
  const double* coarse_velocity(int a) const { return coarse_u_.data() + std::size_t(a) * block_.coarse_size(); }
  const double* fine_velocity(int a) const { return fine_u_.data() + std::size_t(a) * block_.fine_size(); }
  const std::vector<double>& coarse_populations() const { return coarse_; }
  const std::vector<double>& fine_populations() const { return fine_; }

  void step() {
    step([](int) {}, [](int) {});
  }

  // One coarse step with the immersed boundary on the fine level (the membrane steps at dt/2):
  // before(sub) runs before the fine collision of sub-step sub = 0, 1 (spread the force into
  // fine_force there), after(sub) after its streaming (fine_velocity is then that sub-step's
  // physical velocity at the time level of its force, as Fluid::velocity after a step).
  template <class Before, class After>
  void step(Before&& before, After&& after) {
    collide_coarse();
    const double exploded = explode<L>(block_, coarse_.data(), fine_.data());
    for (int sub = 0; sub < 2; ++sub) {
      before(sub);
      collide_fine();
      stream_fine();
      after(sub);
    }
    const double coalesced = stream_coarse();
    restore_mass(exploded + coalesced);
  }

  // The fine lattice as the immersed boundary sees it (solver/ib/grid.hpp: node i at i + 1/2, in
  // fine spacings), and the map of a position in coarse spacings onto it: x_f = 2 (x_c - first),
  // first the coarse cell of fine index 0 (the ghost layer's). Markers must keep their delta's
  // support on block cells (the ghost cells' velocity is not collided).
  std::array<int, 3> fine_grid() const { return {block_.fine_n(0), block_.fine_n(1), D == 3 ? block_.fine_n(2) : 1}; }
  double to_fine(int a, double x_coarse) const { return 2.0 * (x_coarse - block_.fine_centre({0, 0, 0})[a]) + 0.5; }

  // Everything a later step() reads (the forces are spread afresh before each use): a restart
  // point holds it, and import_state makes the next step bitwise the one the saved run took.
  struct State {
    std::vector<double> coarse, fine, coarse_density, coarse_velocity, fine_velocity;
  };
  void export_state(State& out) const { out = {coarse_, fine_, coarse_rho_, coarse_u_, fine_u_}; }
  void import_state(State&& in) {
    if (in.coarse.size() != coarse_.size() || in.fine.size() != fine_.size() || in.coarse_density.size() != coarse_rho_.size() ||
        in.coarse_velocity.size() != coarse_u_.size() || in.fine_velocity.size() != fine_u_.size())
      throw std::invalid_argument("RefinedFluid::import_state: the state is of another lattice or block");
    coarse_ = std::move(in.coarse);
    fine_ = std::move(in.fine);
    coarse_rho_ = std::move(in.coarse_density);
    coarse_u_ = std::move(in.coarse_velocity);
    fine_u_ = std::move(in.fine_velocity);
  }

  // Largest |u| over the uncovered coarse cells and the block's fine cells (lattice velocity,
  // the same number on both levels).
  double max_speed() const {
    double m2 = 0.0;
    const std::size_t N = block_.coarse_size(), F = block_.fine_size();
    for (int z = 0; z < block_.coarse_n(2); ++z)
      for (int y = 0; y < block_.coarse_n(1); ++y)
        for (int x = 0; x < block_.coarse_n(0); ++x) {
          if (block_.covered({x, y, z})) continue;
          const std::size_t n = block_.coarse_index(x, y, z);
          double s = 0.0;
          for (int a = 0; a < D; ++a) s += coarse_u_[a * N + n] * coarse_u_[a * N + n];
          m2 = std::max(m2, s);
        }
    for (int z = 0; z < block_.fine_n(2); ++z)
      for (int y = 0; y < block_.fine_n(1); ++y)
        for (int x = 0; x < block_.fine_n(0); ++x) {
          if (!block_.fine_in_block({x, y, z})) continue;
          const std::size_t n = block_.fine_index(x, y, z);
          double s = 0.0;
          for (int a = 0; a < D; ++a) s += fine_u_[a * F + n] * fine_u_[a * F + n];
          m2 = std::max(m2, s);
        }
    return std::sqrt(m2);
  }

  // Mass (fine cell volumes) the last step's transfers created before restore_mass removed it.
  double last_transfer_mismatch() const { return last_mismatch_; }

  // Mass excess sum (rho - 1) V over the uncovered coarse cells (V = 2^D) and the block cells
  // (V = 1), in fine cell volumes; the populations' mass is the cell count plus this.
  double mass_excess() const {
    double m = 0.0;
    for (int z = 0; z < block_.coarse_n(2); ++z)
      for (int y = 0; y < block_.coarse_n(1); ++y)
        for (int x = 0; x < block_.coarse_n(0); ++x) {
          if (block_.covered({x, y, z})) continue;
          const std::size_t n = block_.coarse_index(x, y, z);
          double s = 0.0;
          for (int i = 0; i < Q; ++i) s += coarse_[n * Q + i] - weight(i);
          m += double(1 << D) * s;
        }
    for (int z = 0; z < block_.fine_n(2); ++z)
      for (int y = 0; y < block_.fine_n(1); ++y)
        for (int x = 0; x < block_.fine_n(0); ++x) {
          if (!block_.fine_in_block({x, y, z})) continue;
          const std::size_t n = block_.fine_index(x, y, z);
          for (int i = 0; i < Q; ++i) m += fine_[n * Q + i] - weight(i);
        }
    return m;
  }

 private:
  static constexpr double weight(int i) { return double(L::weight_numerator[i]) / double(L::weight_denominator); }

  static void equilibrium(double rho, const std::array<double, 3>& u, double* f) {
    double uu = 0.0;
    for (int a = 0; a < D; ++a) uu += u[a] * u[a];
    for (int i = 0; i < Q; ++i) {
      double cu = 0.0;
      for (int a = 0; a < D; ++a) cu += L::c[i][a] * u[a];
      f[i] = weight(i) * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu);
    }
  }

  std::array<int, 3> coarse_cell(long n) const {
    const long nx = block_.coarse_n(0), ny = block_.coarse_n(1);
    return {int(n % nx), int((n / nx) % ny), int(n / (nx * ny))};
  }
  std::array<int, 3> fine_cell(long n) const {
    const long nx = block_.fine_n(0), ny = block_.fine_n(1);
    return {int(n % nx), int((n / nx) % ny), int(n / (nx * ny))};
  }

  void collide_coarse() {
    const long cells = long(block_.coarse_size());
    const std::size_t N = block_.coarse_size();
#pragma omp parallel for schedule(static)
    for (long n = 0; n < cells; ++n) {
      if (block_.covered(coarse_cell(n))) continue;
      double f[Q], force[3], rho, u[3] = {0.0, 0.0, 0.0};
      for (int i = 0; i < Q; ++i) f[i] = coarse_[std::size_t(n) * Q + i];
      for (int a = 0; a < 3; ++a) force[a] = a < D ? coarse_force_[a * N + std::size_t(n)] : 0.0;
      if (collision_ == CollisionModel::trt) Collision<L>::template collide<CollisionModel::trt>(f, force, s_coarse_, rho, u);
      else Collision<L>::collide(f, force, s_coarse_, rho, u);
      for (int i = 0; i < Q; ++i) coarse_[std::size_t(n) * Q + i] = f[i];
      coarse_rho_[std::size_t(n)] = rho;
      for (int a = 0; a < 3; ++a) coarse_u_[a * N + std::size_t(n)] = a < D ? u[a] : 0.0;
    }
  }

  void collide_fine() {
    const long cells = long(block_.fine_size());
    const std::size_t N = block_.fine_size();
#pragma omp parallel for schedule(static)
    for (long n = 0; n < cells; ++n) {
      if (!block_.fine_in_block(fine_cell(n))) continue;
      double f[Q], force[3], rho, u[3] = {0.0, 0.0, 0.0};
      for (int i = 0; i < Q; ++i) f[i] = fine_[std::size_t(n) * Q + i];
      for (int a = 0; a < 3; ++a) force[a] = a < D ? fine_force_[a * N + std::size_t(n)] : 0.0;
      if (collision_ == CollisionModel::trt) Collision<L>::template collide<CollisionModel::trt>(f, force, s_fine_, rho, u);
      else Collision<L>::collide(f, force, s_fine_, rho, u);
      for (int i = 0; i < Q; ++i) fine_[std::size_t(n) * Q + i] = f[i];
      for (int a = 0; a < 3; ++a) fine_u_[a * N + std::size_t(n)] = a < D ? u[a] : 0.0;
    }
  }

  // Pull streaming over the whole fine lattice; a ghost cell whose source lies outside keeps
  // its value (it never reaches the block nor a coalescence, coalescence.hpp).
  void stream_fine() {
    const long cells = long(block_.fine_size());
#pragma omp parallel for schedule(static)
    for (long n = 0; n < cells; ++n) {
      const std::array<int, 3> x = fine_cell(n);
      for (int i = 0; i < Q; ++i) {
        std::array<int, 3> s = x;
        for (int a = 0; a < D; ++a) s[a] -= L::c[i][a];
        const bool inside = block_.wrap_fine(s);
        fine_next_[std::size_t(n) * Q + i] =
            inside ? fine_[block_.fine_index(s[0], s[1], s[2]) * Q + i] : fine_[std::size_t(n) * Q + i];
      }
    }
    std::swap(fine_, fine_next_);
  }

  // Returns the mass the coalescence created (fine cell volumes).
  double stream_coarse() {
    using B = MomentBasis<L>;
    const long cells = long(block_.coarse_size());
    const int ny = block_.coarse_n(1);
    std::fill(moved_.begin(), moved_.end(), 0.0);
#pragma omp parallel for schedule(static)
    for (long n = 0; n < cells; ++n) {
      const std::array<int, 3> R = coarse_cell(n);
      if (block_.covered(R)) continue;
      for (int i = 0; i < Q; ++i) {
        double& out = coarse_next_[std::size_t(n) * Q + i];
        const int ys = R[1] - L::c[i][1];
        if (ys < 0 || ys >= ny) {
          // Half-way bounce-back with the moving-wall term (fluid.hpp): c_i points away from the wall.
          const double uw = ys < 0 ? u_bottom_ : u_top_;
          out = coarse_[std::size_t(n) * Q + B::opposite[i]] + 6.0 * weight(i) * coarse_rho_[std::size_t(n)] * L::c[i][0] * uw;
        } else if (from_fine<L>(block_, R, i)) {
          double moved = 0.0;
          out = coalesce<L>(block_, coarse_.data(), fine_.data(), R, i, moved);
          moved_[std::size_t(n)] -= moved;
        } else {
          std::array<int, 3> S = R;
          for (int a = 0; a < D; ++a) {
            S[a] -= L::c[i][a];
            if (a != 1) S[a] = (S[a] % block_.coarse_n(a) + block_.coarse_n(a)) % block_.coarse_n(a);
          }
          out = coarse_[block_.coarse_index(S[0], S[1], S[2]) * Q + i];
        }
      }
    }
    std::swap(coarse_, coarse_next_);
    double created = 0.0;
    for (std::size_t r : ring_cells_) created += moved_[r];
    return created;
  }

  // Removes the mass the transfers created at the block's edges and corners (explosion.hpp,
  // coalescence.hpp) from the rest populations of the ring cells, evenly: zero in a steady
  // flow linear in space, where both lattices hold their exact solutions.
  void restore_mass(double created) {
    last_mismatch_ = created;
    const double per_population = created / (double(1 << D) * double(ring_cells_.size()));
    for (std::size_t r : ring_cells_) coarse_[r * Q] -= per_population;
  }

  Block block_;
  double s_coarse_, s_fine_;
  double u_bottom_ = 0.0, u_top_ = 0.0;
  CollisionModel collision_ = CollisionModel::mrt;
  std::vector<double> coarse_, coarse_next_, fine_, fine_next_;
  std::vector<double> coarse_force_, fine_force_;
  std::vector<double> coarse_rho_, coarse_u_, fine_u_;
  std::vector<std::size_t> ring_cells_;  // ascending index: the sums are in a fixed order
  std::vector<double> moved_;
  double last_mismatch_ = 0.0;
};

}  // namespace capsule::lbm::refinement
