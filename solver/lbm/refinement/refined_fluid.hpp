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
// Storage: the populations are shifted, g_i = f_i - w_i (split_collision.hpp, as Fluid stores
// them), by direction (RefinedBlock::coarse_at). The transfers and the bounce-back are linear
// with coefficients that sum to one, so they act on g as on f.
//
// Units: everything is in the lattice units of its own level. The coarse force and the coarse
// velocity are in coarse units; the fine force is in fine units (a body-force density F_c on the
// coarse lattice is F_c / 2 on the fine one), the fine velocity likewise (the same number as in
// coarse units). After step() the coarse velocity is that of coarse level n (fluid.hpp) and the
// fine velocity that of the second sub-step, fine level 2n + 1.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "solver/lbm/collide_and_bounce.hpp"  // CAPSULE_LBM_FAST_CLONE_ATTR
#include "solver/lbm/collision.hpp"
#include "solver/lbm/split_collision.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/precision.hpp"
#include "solver/lbm/refinement/coalescence.hpp"
#include "solver/lbm/refinement/explosion.hpp"
#include "solver/lbm/refinement/refined_block.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/lbm/static_for.hpp"

namespace capsule::lbm::refinement {

// Collides `length` consecutive cells from `first` (populations by direction, N cells per
// direction, shifted) and writes population i of cell n to out + i N + n + offset[i]: in place
// (out = pop, offsets zero) or pushed to its neighbour in the next lattice (streaming fused
// with the collision). One vector loop over pointers per direction, unrolled over the
// directions like Fluid's rows (collide_and_bounce.hpp) so that it vectorises, cloned per
// CPU. The arithmetic is that of the storage, T (as Fluid's single precision: float
// populations collide in float). With macro, the cells read the force and write u (and rho
// when with_rho); without, they collide with zero force and write neither (the same
// populations, bitwise, when the force is zero: the same operations, as in Fluid's unflagged
// rows).
template <class L, class T, bool trt, bool with_rho, bool macro = true>
[[gnu::flatten]] CAPSULE_LBM_FAST_CLONE_ATTR void collide_run(const T* pop, T* out, const std::array<long, L::Q>& offset,
                                                              std::size_t N, const double* force, double s_nu, double* rho_out,
                                                              double* u_out, std::size_t first, int length) {
  constexpr int Q = L::Q, D = L::D;
  const T* g[Q];
  T* o[Q];
  static_for<Q>([&](auto i) __attribute__((always_inline)) {
    g[i] = pop + std::size_t(i) * N + first;
    o[i] = out + std::size_t(i) * N + std::size_t(long(first) + offset[i]);
  });
  const double* F[D];
  double* u[3];
  static_for<D>([&](auto a) __attribute__((always_inline)) { F[a] = force + std::size_t(a) * N + first; });
  static_for<3>([&](auto a) __attribute__((always_inline)) { u[a] = u_out + std::size_t(a) * N + first; });
  double* rho_row = with_rho ? rho_out + first : nullptr;
#pragma omp simd
  for (int m = 0; m < length; ++m) {
    using A = T;
    A f[Q], Fm[3] = {A(0), A(0), A(0)}, rho, um[3] = {A(0), A(0), A(0)};
    static_for<Q>([&](auto i) __attribute__((always_inline)) { f[i] = A(g[i][m]); });
    if constexpr (macro) static_for<D>([&](auto a) __attribute__((always_inline)) { Fm[a] = A(F[a][m]); });
    SplitCollision<L, A>::template collide<true, trt>(f, Fm, A(s_nu), rho, um);
    static_for<Q>([&](auto i) __attribute__((always_inline)) { o[i][m] = T(f[i]); });
    if constexpr (macro && with_rho) rho_row[m] = rho;
    if constexpr (macro) static_for<3>([&](auto a) __attribute__((always_inline)) { u[a][m] = a < D ? um[a] : 0.0; });
  }
}

template <class L>
class RefinedFluid {
  // The populations of both levels and their next lattices in one precision.
  template <class T>
  struct Levels {
    std::vector<T> coarse, coarse_next, fine, fine_next;
  };

 public:
  static constexpr int Q = L::Q;
  static constexpr int D = L::D;
  using Block = RefinedBlock<D>;

  // nu: kinematic viscosity in coarse lattice units; starts at rest, rho = 1. The populations
  // are stored and collided in `precision` (single: floats, half the memory traffic and twice
  // the vector width, as Fluid's single precision; the transfers and walls compute in double
  // either way; single conserves the mass to float round-off instead of double's).
  RefinedFluid(int nx, int ny, int nz, double nu, const BlockExtent& extent,
               Precision precision = Precision::double_precision)
      : block_(nx, ny, nz, extent),
        s_coarse_(shear_rate_from_viscosity(nu)),
        s_fine_(shear_rate_from_viscosity(2.0 * nu)),
        single_precision_(precision == Precision::single_precision),
        coarse_force_(3 * block_.coarse_size(), 0.0),
        fine_force_(3 * block_.fine_size(), 0.0),
        coarse_rho_(block_.coarse_size(), 1.0),
        coarse_u_(3 * block_.coarse_size(), 0.0),
        fine_u_(3 * block_.fine_size(), 0.0),
        ring_(block_) {
    if (!(nu > 0.0)) throw std::invalid_argument("RefinedFluid: viscosity must be positive");
    on_levels([&](auto& p) {
      p.coarse.resize(block_.coarse_size() * Q);
      p.coarse_next.resize(p.coarse.size());
      p.fine.resize(block_.fine_size() * Q);
      p.fine_next.resize(p.fine.size());
    });
    for (const auto& c : ring_.cells) ring_cells_.push_back(c.coarse);
    moved_.assign(ring_cells_.size(), 0.0);
    classify_cells();
    initialise_velocity([](double, double, double) { return std::array<double, 3>{0.0, 0.0, 0.0}; });
  }

  const Block& block() const { return block_; }
  Precision precision() const { return single_precision_ ? Precision::single_precision : Precision::double_precision; }
  double shear_rate_coarse() const { return s_coarse_; }
  double shear_rate_fine() const { return s_fine_; }

  // The relaxation rates of both levels (relaxation.hpp): mrt, or trt with Lambda = 3/16.
  void set_collision(CollisionModel model) { collision_ = model; }

  // The coarse fields. On (the default), every coarse cell reads the coarse force and writes u
  // and rho. Off, the cells away from the walls and the block neither read the force (taken as
  // zero) nor write u and rho (the populations bitwise the same when the coarse force is zero):
  // a driver whose force lives on the fine level only turns it on for the steps whose velocity
  // it reads (max_speed), and saves the force read and the u and rho writes on the others.
  void set_coarse_fields(bool on) { coarse_fields_ = on; }

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
          double f[Q];
          equilibrium(1.0, v, f);
          on_levels([&](auto& p) {
            for (int i = 0; i < Q; ++i) p.coarse[block_.coarse_at(n, i)] = f[i];
          });
          for (int a = 0; a < 3; ++a) coarse_u_[a * block_.coarse_size() + n] = a < D ? v[a] : 0.0;
        }
    for (int z = 0; z < block_.fine_n(2); ++z)
      for (int y = 0; y < block_.fine_n(1); ++y)
        for (int x = 0; x < block_.fine_n(0); ++x) {
          const std::size_t n = block_.fine_index(x, y, z);
          const auto p = block_.fine_centre({x, y, z});
          const auto v = u(p[0], p[1], p[2]);
          double f[Q];
          equilibrium(1.0, v, f);
          on_levels([&](auto& p) {
            for (int i = 0; i < Q; ++i) p.fine[block_.fine_at(n, i)] = f[i];
          });
          for (int a = 0; a < 3; ++a) fine_u_[a * block_.fine_size() + n] = a < D ? v[a] : 0.0;
        }
  }

  double* coarse_force(int a) { return coarse_force_.data() + std::size_t(a) * block_.coarse_size(); }
  double* fine_force(int a) { return fine_force_.data() + std::size_t(a) * block_.fine_size(); }
  const double* coarse_velocity(int a) const { return coarse_u_.data() + std::size_t(a) * block_.coarse_size(); }
  const double* fine_velocity(int a) const { return fine_u_.data() + std::size_t(a) * block_.fine_size(); }
  // The populations (shifted, by direction), as doubles.
  std::vector<double> coarse_populations() const {
    return on_levels([](const auto& p) { return std::vector<double>(p.coarse.begin(), p.coarse.end()); });
  }
  std::vector<double> fine_populations() const {
    return on_levels([](const auto& p) { return std::vector<double>(p.fine.begin(), p.fine.end()); });
  }

  void step() {
    step([](int) {}, [](int) {});
  }

  // One coarse step with the immersed boundary on the fine level (the membrane steps at dt/2):
  // before(sub) runs before the fine collision of sub-step sub = 0, 1 (spread the force into
  // fine_force there), after(sub) after its streaming (fine_velocity is then that sub-step's
  // physical velocity at the time level of its force, as Fluid::velocity after a step).
  template <class Before, class After>
  void step(Before&& before, After&& after) {
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    on_levels([&](auto& p) {
      auto t = Clock::now();
      collide_coarse(p);
      seconds_.coarse += since(t);
      t = Clock::now();
      const double exploded = explode<L>(block_, ring_, p.coarse.data(), p.fine.data(), taylor_);
      seconds_.transfers += since(t);
      for (int sub = 0; sub < 2; ++sub) {
        before(sub);
        t = Clock::now();
        collide_and_stream_fine(p);
        seconds_.fine += since(t);
        after(sub);
      }
      const double coalesced = stream_coarse(p);
      t = Clock::now();
      restore_mass(p, exploded + coalesced);
      seconds_.transfers += since(t);
    });
  }

  // Seconds spent so far (this process) per part of step(): the coarse lattice's collision and
  // streaming, the fine lattice's sub-steps, and the transfers (explosion, coalescence, the
  // mass balance). Measured only; nothing depends on them.
  struct Seconds {
    double coarse = 0.0, fine = 0.0, transfers = 0.0;
  };
  const Seconds& seconds() const { return seconds_; }

  // The fine lattice as the immersed boundary sees it (solver/ib/grid.hpp: node i at i + 1/2, in
  // fine spacings), and the map of a position in coarse spacings onto it: x_f = 2 (x_c - first),
  // first the coarse cell of fine index 0 (the ghost layer's). Markers must keep their delta's
  // support on block cells (the ghost cells' velocity is not collided).
  std::array<int, 3> fine_grid() const { return {block_.fine_n(0), block_.fine_n(1), D == 3 ? block_.fine_n(2) : 1}; }
  double to_fine(int a, double x_coarse) const { return 2.0 * (x_coarse - block_.fine_centre({0, 0, 0})[a]) + 0.5; }

  // Everything a later step() reads (the forces are spread afresh before each use): a restart
  // point holds it, and import_state makes the next step bitwise the one the saved run took
  // (single-precision populations travel as doubles, exactly).
  struct State {
    std::vector<double> coarse, fine, coarse_density, coarse_velocity, fine_velocity;
  };
  void export_state(State& out) const { out = {coarse_populations(), fine_populations(), coarse_rho_, coarse_u_, fine_u_}; }
  void import_state(State&& in) {
    if (in.coarse.size() != block_.coarse_size() * Q || in.fine.size() != block_.fine_size() * Q ||
        in.coarse_density.size() != coarse_rho_.size() || in.coarse_velocity.size() != coarse_u_.size() ||
        in.fine_velocity.size() != fine_u_.size())
      throw std::invalid_argument("RefinedFluid::import_state: the state is of another lattice or block");
    on_levels([&](auto& p) {
      std::copy(in.coarse.begin(), in.coarse.end(), p.coarse.begin());
      std::copy(in.fine.begin(), in.fine.end(), p.fine.begin());
    });
    coarse_rho_ = std::move(in.coarse_density);
    coarse_u_ = std::move(in.coarse_velocity);
    fine_u_ = std::move(in.fine_velocity);
  }

  // Largest |u| over the uncovered coarse cells and the block's fine cells (lattice velocity,
  // the same number on both levels).
  double max_speed() const {
    double m2 = 0.0;
    const auto largest = [&](const std::vector<Span>& spans, const std::vector<double>& u, std::size_t N) {
      for_each_cell(spans, [&](std::size_t n) {
        double s = 0.0;
        for (int a = 0; a < D; ++a) s += u[a * N + n] * u[a * N + n];
        m2 = std::max(m2, s);
      });
    };
    largest(coarse_collide_, coarse_u_, block_.coarse_size());
    largest(fine_collide_, fine_u_, block_.fine_size());
    return std::sqrt(m2);
  }

  // Mass (fine cell volumes) the last step's transfers created before restore_mass removed it.
  double last_transfer_mismatch() const { return last_mismatch_; }

  // Mass excess sum (rho - 1) V over the uncovered coarse cells (V = 2^D) and the block cells
  // (V = 1), in fine cell volumes; the populations' mass is the cell count plus this.
  double mass_excess() const {
    double m = 0.0;
    const auto add = [&](const std::vector<Span>& spans, const auto& f, std::size_t N, double volume) {
      for_each_cell(spans, [&](std::size_t n) {
        double sum = 0.0;
        for (int i = 0; i < Q; ++i) sum += f[std::size_t(i) * N + n];
        m += volume * sum;
      });
    };
    on_levels([&](const auto& p) {
      add(coarse_collide_, p.coarse, block_.coarse_size(), double(1 << D));
      add(fine_collide_, p.fine, block_.fine_size(), 1.0);
    });
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
      f[i] = weight(i) * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu) - weight(i);  // shifted
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

  // Runs of consecutive cell indices (at most kSpan long, so that the threads share them
  // evenly and the split does not depend on their number).
  struct Span {
    std::size_t start;
    int length;
  };
  static constexpr int kSpan = 256;
  template <class F>
  static void for_each_cell(const std::vector<Span>& spans, F&& f) {
    for (const Span& r : spans)
      for (int m = 0; m < r.length; ++m) f(r.start + std::size_t(m));
  }
  static std::vector<Span> spans_of(const std::vector<std::size_t>& cells) {
    std::vector<Span> out;
    for (std::size_t c : cells) {
      if (!out.empty() && out.back().start + std::size_t(out.back().length) == c && out.back().length < kSpan) ++out.back().length;
      else out.push_back({c, 1});
    }
    return out;
  }

  // Collides the cells of `spans` (the runs shared among the threads), in place (out = pop,
  // offsets zero) or pushing every population to its neighbour in `out`.
  template <bool trt, bool with_rho, bool macro, class T>
  static void collide_spans(const std::vector<Span>& spans, const T* pop, T* out, const std::array<long, Q>& offset,
                            std::size_t N, const double* force, double s_nu, double* rho_out, double* u_out) {
    const long count = long(spans.size());
#pragma omp parallel for schedule(static)
    for (long k = 0; k < count; ++k)
      collide_run<L, T, trt, with_rho, macro>(pop, out, offset, N, force, s_nu, rho_out, u_out, spans[std::size_t(k)].start,
                                    spans[std::size_t(k)].length);
  }
  template <bool with_rho, bool macro = true, class T>
  void collide_level(const std::vector<Span>& spans, std::vector<T>& pop, T* out, const std::array<long, Q>& offset,
                     const std::vector<double>& force, double s_nu, double* rho_out, std::vector<double>& u) {
    const std::size_t N = pop.size() / Q;
    if (collision_ == CollisionModel::trt)
      collide_spans<true, with_rho, macro>(spans, pop.data(), out, offset, N, force.data(), s_nu, rho_out, u.data());
    else
      collide_spans<false, with_rho, macro>(spans, pop.data(), out, offset, N, force.data(), s_nu, rho_out, u.data());
  }

  // The coarse collision: the cells the transfers and the table streaming read collide in
  // place; the others collide and stream in one pass into the next lattice.
  template <class T>
  void collide_coarse(Levels<T>& p) {
    collide_level<true>(coarse_in_place_, p.coarse, p.coarse.data(), zero_offset_, coarse_force_, s_coarse_, coarse_rho_.data(),
                        coarse_u_);
    if (coarse_fields_)
      collide_level<true>(coarse_fused_, p.coarse, p.coarse_next.data(), coarse_offset_, coarse_force_, s_coarse_,
                          coarse_rho_.data(), coarse_u_);
    else
      collide_level<true, false>(coarse_fused_, p.coarse, p.coarse_next.data(), coarse_offset_, coarse_force_, s_coarse_,
                                 coarse_rho_.data(), coarse_u_);
  }

  // One fine sub-step: collision and streaming (fused where the cell streams at fixed offsets),
  // the ghost layer streamed uncollided.
  template <class T>
  void collide_and_stream_fine(Levels<T>& p) {
    collide_level<false>(fine_in_place_, p.fine, p.fine.data(), zero_offset_, fine_force_, s_fine_, nullptr, fine_u_);
    collide_level<false>(fine_fused_, p.fine, p.fine_next.data(), fine_offset_, fine_force_, s_fine_, nullptr, fine_u_);
    push_spans(fine_copy_, p.fine.data(), p.fine_next.data(), block_.fine_size(), fine_offset_);
    push_table(fine_push_cells_, fine_push_, p.fine.data(), p.fine_next.data(), block_.fine_size());
    const long kept = long(fine_keep_.size());
#pragma omp parallel for schedule(static)
    for (long k = 0; k < kept; ++k) p.fine_next[fine_keep_[std::size_t(k)]] = p.fine[fine_keep_[std::size_t(k)]];
    std::swap(p.fine, p.fine_next);
  }

  // Pushes the post-collision populations of the runs `spans` (collided in place) to their
  // neighbours at a fixed index offset: one contiguous copy per direction.
  template <class T>
  static void push_spans(const std::vector<Span>& spans, const T* from, T* to, std::size_t N,
                         const std::array<long, Q>& offset) {
    const long count = long(spans.size());
#pragma omp parallel for schedule(static)
    for (long k = 0; k < count; ++k) {
      const std::size_t first = spans[std::size_t(k)].start;
      const int length = spans[std::size_t(k)].length;
      for (int i = 0; i < Q; ++i) {
        const T* src = from + std::size_t(i) * N + first;
        T* dst = to + std::size_t(i) * N + std::size_t(long(first) + offset[i]);
#pragma omp simd
        for (int m = 0; m < length; ++m) dst[m] = src[m];
      }
    }
  }

  // Pushes the populations of the tabled cells: entry (c, i) the slot of `to` that population
  // i of cell cells[c] goes to, or kNowhere.
  template <class T>
  static void push_table(const std::vector<std::size_t>& cells, const std::vector<long>& slot, const T* from, T* to,
                         std::size_t N) {
    const long count = long(cells.size());
#pragma omp parallel for schedule(static)
    for (long c = 0; c < count; ++c) {
      const std::size_t n = cells[std::size_t(c)];
      for (int i = 0; i < Q; ++i) {
        const long to_slot = slot[std::size_t(c) * Q + std::size_t(i)];
        if (to_slot >= 0) to[to_slot] = from[std::size_t(i) * N + n];
      }
    }
  }

  // Streams the coarse lattice: the in-place cells push (at fixed offsets, through the table,
  // or bounced back at a wall: half-way bounce-back with the moving-wall term of fluid.hpp);
  // ring cells take the populations that come from the fine lattice as children averages.
  // Returns the mass the coalescence created (fine cell volumes).
  template <class T>
  double stream_coarse(Levels<T>& p) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const std::size_t N = block_.coarse_size();
    push_spans(coarse_copy_, p.coarse.data(), p.coarse_next.data(), N, coarse_offset_);
    push_table(coarse_push_cells_, coarse_push_, p.coarse.data(), p.coarse_next.data(), N);
    const long walls = long(coarse_wall_.size());
#pragma omp parallel for schedule(static)
    for (long k = 0; k < walls; ++k) {
      // Population j of cell n leaves through a wall and comes back as i = opposite(j), which
      // points away from it.
      const WallEntry& w = coarse_wall_[std::size_t(k)];
      const int i = MomentBasis<L>::opposite[w.j];
      const double uw = L::c[i][1] > 0 ? u_bottom_ : u_top_;
      p.coarse_next[std::size_t(i) * N + w.cell] =
          T(double(p.coarse[std::size_t(w.j) * N + w.cell]) + 6.0 * weight(i) * coarse_rho_[w.cell] * L::c[i][0] * uw);
    }
    const auto coalescence = Clock::now();
    seconds_.coarse += std::chrono::duration<double>(coalescence - start).count();
    const long ring = long(ring_cells_.size());
#pragma omp parallel for schedule(static)
    for (long r = 0; r < ring; ++r) {
      const std::size_t n = ring_cells_[std::size_t(r)];
      double moved_here = 0.0;
      for (int i = 0; i < Q; ++i) {
        if (!ring_.from_fine[std::size_t(r) * Q + std::size_t(i)]) continue;
        double moved = 0.0;
        p.coarse_next[std::size_t(i) * N + n] = T(coalesce<L>(block_, ring_, taylor_, p.fine.data(), std::size_t(r), i, moved));
        moved_here -= moved;
      }
      moved_[std::size_t(r)] = moved_here;
    }
    std::swap(p.coarse, p.coarse_next);
    double created = 0.0;
    for (double m : moved_) created += m;
    seconds_.transfers += std::chrono::duration<double>(Clock::now() - coalescence).count();
    return created;
  }

  // The cells each pass visits, once. Collided cells whose populations all stream at a fixed
  // index offset (no wall, no wrap, no transfer) and which no transfer reads collide and
  // stream in one pass; the others collide in place (the explosion reads the ring's
  // post-collision populations and its Taylor stencil two cells beyond), then stream by
  // contiguous copies where the offsets are fixed or through a table (walls, wraps, the
  // ring, the ghost layer). Every slot of the next lattice has one writer.
  void classify_cells() {
    for (int i = 0; i < Q; ++i) {
      coarse_offset_[i] = long(L::c[i][0]) + long(block_.coarse_n(0)) * (long(L::c[i][1]) + long(block_.coarse_n(1)) * long(D == 3 ? L::c[i][2] : 0));
      fine_offset_[i] = long(L::c[i][0]) + long(block_.fine_n(0)) * (long(L::c[i][1]) + long(block_.fine_n(1)) * long(D == 3 ? L::c[i][2] : 0));
    }
    const std::size_t N = block_.coarse_size();
    const int ny = block_.coarse_n(1);
    // Within two coarse cells of the fine lattice (the Taylor stencils' reach) on every axis
    // the block does not span.
    const auto near_fine_lattice = [&](const std::array<int, 3>& R) {
      for (int a = 0; a < D; ++a)
        if (!block_.spans(a) && (R[a] < block_.begin(a) - 3 || R[a] > block_.end(a) + 2)) return false;
      return true;
    };
    std::vector<std::size_t> collided, fused, in_place, copy;
    for (long n = 0; n < long(N); ++n) {
      const std::array<int, 3> R = coarse_cell(n);
      if (block_.covered(R)) continue;
      collided.push_back(std::size_t(n));
      bool interior = !block_.ring(R);
      for (int a = 0; a < D; ++a) interior = interior && R[a] >= 1 && R[a] <= block_.coarse_n(a) - 2;
      if (interior && !near_fine_lattice(R)) {
        fused.push_back(std::size_t(n));
        continue;
      }
      in_place.push_back(std::size_t(n));
      if (interior) {
        copy.push_back(std::size_t(n));
        continue;
      }
      coarse_push_cells_.push_back(std::size_t(n));
      for (int j = 0; j < Q; ++j) {
        std::array<int, 3> S = R;
        for (int a = 0; a < D; ++a) {
          S[a] += L::c[j][a];
          if (a != 1) S[a] = (S[a] % block_.coarse_n(a) + block_.coarse_n(a)) % block_.coarse_n(a);
        }
        if (S[1] < 0 || S[1] >= ny) {
          coarse_push_.push_back(kNowhere);
          coarse_wall_.push_back({std::size_t(n), j});
        } else if (block_.ring(R) && block_.in_fine_lattice(S)) {
          coarse_push_.push_back(kNowhere);  // covered, or a ring cell that takes it from the fine lattice
        } else {
          coarse_push_.push_back(long(std::size_t(j) * N + block_.coarse_index(S[0], S[1], S[2])));
        }
      }
    }
    coarse_collide_ = spans_of(collided);
    coarse_fused_ = spans_of(fused);
    coarse_in_place_ = spans_of(in_place);
    coarse_copy_ = spans_of(copy);

    const std::size_t F = block_.fine_size();
    collided.clear();
    fused.clear();
    in_place.clear();
    copy.clear();
    for (long n = 0; n < long(F); ++n) {
      const std::array<int, 3> x = fine_cell(n);
      const bool in_block = block_.fine_in_block(x);
      bool inner = true;  // every population streams at a fixed offset
      for (int a = 0; a < D; ++a) inner = inner && x[a] >= 1 && x[a] <= block_.fine_n(a) - 2;
      if (in_block) collided.push_back(std::size_t(n));
      if (in_block && inner) {
        fused.push_back(std::size_t(n));
        continue;
      }
      if (in_block) in_place.push_back(std::size_t(n));
      if (inner) {
        copy.push_back(std::size_t(n));
        continue;
      }
      fine_push_cells_.push_back(std::size_t(n));
      for (int j = 0; j < Q; ++j) {
        std::array<int, 3> to = x, from = x;
        for (int a = 0; a < D; ++a) {
          to[a] += L::c[j][a];
          from[a] -= L::c[j][a];
        }
        fine_push_.push_back(block_.wrap_fine(to) ? long(std::size_t(j) * F + block_.fine_index(to[0], to[1], to[2])) : kNowhere);
        // A ghost cell whose source lies outside keeps its value (it never reaches the block).
        if (!block_.wrap_fine(from)) fine_keep_.push_back(std::size_t(j) * F + std::size_t(n));
      }
    }
    fine_collide_ = spans_of(collided);
    fine_fused_ = spans_of(fused);
    fine_in_place_ = spans_of(in_place);
    fine_copy_ = spans_of(copy);
  }

  // Removes the mass the transfers created at the block's edges and corners (explosion.hpp,
  // coalescence.hpp) from the rest populations of the ring cells, evenly: zero in a steady
  // flow linear in space, where both lattices hold their exact solutions.
  template <class T>
  void restore_mass(Levels<T>& p, double created) {
    last_mismatch_ = created;
    const double per_population = created / (double(1 << D) * double(ring_cells_.size()));
    for (std::size_t r : ring_cells_) {
      T& rest = p.coarse[block_.coarse_at(r, 0)];
      rest = T(double(rest) - per_population);
    }
  }

  Block block_;
  double s_coarse_, s_fine_;
  double u_bottom_ = 0.0, u_top_ = 0.0;
  CollisionModel collision_ = CollisionModel::mrt;
  bool coarse_fields_ = true;
  // The populations of both levels and their next lattices, in the precision chosen (the other
  // stays empty); on_levels calls f with the one in use.
  bool single_precision_;
  Levels<double> double_;
  Levels<float> single_;
  template <class F>
  decltype(auto) on_levels(F&& f) {
    return single_precision_ ? f(single_) : f(double_);
  }
  template <class F>
  decltype(auto) on_levels(F&& f) const {
    return single_precision_ ? f(single_) : f(double_);
  }
  std::vector<double> coarse_force_, fine_force_;
  std::vector<double> coarse_rho_, coarse_u_, fine_u_;
  RingPlan<L> ring_;                     // the transfers' geometry
  std::vector<Taylor> taylor_;           // the explosion's coefficients, per (ring cell, i), for the coalescence
  std::vector<std::size_t> ring_cells_;  // ascending index: the sums are in a fixed order
  std::vector<double> moved_;             // per ring cell: the mass its coalescence created
  // classify_cells(): the collided cells (both levels), those that collide and stream in one
  // pass, those that collide in place, and how the in-place and ghost cells stream.
  std::vector<Span> coarse_collide_, fine_collide_, coarse_fused_, fine_fused_, coarse_in_place_, fine_in_place_, coarse_copy_,
      fine_copy_;
  // Per tabled cell and direction: the slot of the next lattice the population goes to, or
  // kNowhere (it leaves the lattice, or a transfer or a wall fills its slot).
  static constexpr long kNowhere = -1;
  std::vector<std::size_t> coarse_push_cells_, fine_push_cells_;
  std::vector<long> coarse_push_, fine_push_;
  struct WallEntry {
    std::size_t cell;
    int j;  // the direction that leaves through the wall
  };
  std::vector<WallEntry> coarse_wall_;
  std::vector<std::size_t> fine_keep_;  // slots a ghost cell keeps (their source lies outside)
  std::array<long, Q> coarse_offset_{}, fine_offset_{}, zero_offset_{};
  double last_mismatch_ = 0.0;
  Seconds seconds_;
};

}  // namespace capsule::lbm::refinement
