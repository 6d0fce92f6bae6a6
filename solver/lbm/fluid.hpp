#pragma once
// The lattice Boltzmann fluid (Sec. 2.1, docs/guide/model.md "Fluid"): MRT collision (2) with
// Peng and Luo's body force (22)-(23), half-way bounce-back moving walls at y = 0 and y = ny,
// periodic in x and z; dx = dt = rho0 = 1, node (i, j, k) at (i, j, k) + 1/2, x fastest
// (docs/CONTRACTS.md). nz = 1 for D2Q9.
// Time levels: step() takes f(n) and the force F set before it, and leaves f(n+1) with
// density() and velocity() at level n (22), the level of the force, which the immersed
// boundary interpolates to move the membrane from X(n) to X(n+1) (19)-(20); a time-dependent
// wall velocity is best given at t = n + 1/2.
// The kernels: the split collision (split_collision.hpp) on populations f_i - w_i in double or
// float (precision.hpp), streamed in place (in_place_stream_collide.hpp) or between two arrays
// (shifted_stream_collide.hpp, the reference the in-place scheme is tested against).
// set_macroscopic_region() restricts reading F and writing rho, u to the rows around the
// membrane (bitwise the same populations: tests/solver/lbm/macroscopic_region_test.cpp);
// set_viscosity() gives nodes their own nu = (1/s_nu - 1/2)/3 (8), (13); set_collision() picks
// MRT or TRT rates (relaxation.hpp). The staggered mode u_x ~ (-1)^(x+t) is never damped; a
// force alternating from node to node excites it (stop_shear_test: ~1e-10 U).
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "solver/lbm/huge_page_allocator.hpp"
#include "solver/lbm/lattice.hpp"
#include "solver/lbm/padded_rows.hpp"
#include "solver/lbm/precision.hpp"
#include "solver/lbm/relaxation.hpp"

namespace capsule::lbm {

enum class Streaming { in_place, two_lattice };

template <class L>
class Fluid {
 public:
  static constexpr int Q = L::Q;
  static constexpr int D = L::D;

  // nz = 1 for D2Q9; starts at rest, rho = 1.
  Fluid(int nx, int ny, int nz, double nu, Precision precision = Precision::double_precision,
        Streaming streaming = Streaming::in_place);
  Precision precision() const { return precision_; }
  Streaming streaming() const { return streaming_; }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  std::size_t size() const { return n_; }
  std::size_t index(int x, int y, int z = 0) const {
    return std::size_t(x) + std::size_t(nx_) * (std::size_t(y) + std::size_t(ny_) * std::size_t(z));
  }

  // x-velocity of the walls at y = 0 and y = ny, used by the next step().
  void set_wall_velocity(double u_bottom, double u_top);
  double wall_velocity_bottom() const { return u_bottom_; }
  double wall_velocity_top() const { return u_top_; }

  // Equilibrium (5) at rho = 1 with velocity u(x, y, z) at the node centres.
  void initialise_velocity(const std::function<std::array<double, 3>(double x, double y, double z)>& u);

  double* force(int d) { return force_.data() + std::size_t(d) * n_; }  // body-force density, component d
  const double* force(int d) const { return force_.data() + std::size_t(d) * n_; }
  void clear_force();

  void step();

  // Rows y in [y_begin, y_end) (clipped to the channel) and z in [z_begin, z_end) (periodic:
  // any integers, wrapped; a range of nz or more is every z). Whole x-rows.
  struct RowBox {
    int y_begin, y_end, z_begin, z_end;
  };
  // From the next step on, F is read and rho, u written only in the rows that meet the boxes;
  // elsewhere the force is ignored (taken as zero) and density()/velocity() keep stale values.
  void set_macroscopic_region(const std::vector<RowBox>& boxes);
  void set_macroscopic_everywhere();
  bool macroscopic_everywhere() const { return macroscopic_rows_.empty(); }
  // Fraction of the rows the next step writes rho, u for (1 when everywhere).
  double macroscopic_fraction() const;

  const double* velocity(int d) const { return velocity_.data() + std::size_t(d) * n_; }
  const double* density() const { return density_.data(); }

  // Switches on the per-node field on first use; marks the node if nu changed (only marked
  // nodes get their s_nu recomputed at the next step). Not thread-safe: call from one thread.
  void set_viscosity(std::size_t node, double nu);
  void set_uniform_viscosity(double nu);
  double viscosity(std::size_t node) const;
  bool has_viscosity_field() const { return !node_viscosity_.empty(); }

  // The relaxation rates' model (relaxation.hpp); mrt unless set. Not State: the driver sets it
  // from the scene, like the wall velocity.
  void set_collision(CollisionModel model) { collision_ = model; }
  CollisionModel collision() const { return collision_; }

  // Sum of all populations (the conserved mass), summed in a fixed order.
  double total_mass() const;

  // Populations f_i at a node (pre-collision, current level) -- for tests and diagnostics
  // (stored as f_i - w_i, in place: where f_i of a node sits alternates every step; a
  // checkpoint can export and import them node by node through this accessor and a setter
  // built on slot(), in either precision).
  double population(int i, std::size_t node) const;

  // Density and momentum of the current (pre-collision) populations at a node: {rho, j_x, j_y,
  // j_z} with j = sum f c, i.e. what the next step() turns into u = (j + F/2)/rho (22) before
  // the force is known. The 2D driver's exact Kelvin-Voigt step splits the node velocity into
  // this force-free part and the part the step's own force adds (solver/ib/mobility.hpp).
  std::array<double, 4> moments(std::size_t node) const;

  // Save and restore for restart points (solver/run/checkpoint.hpp): everything a later step()
  // depends on, in an order that does not depend on the memory layout, so that a new layout
  // re-implements only these two functions.
  //   populations  Q n values, f_i(node) - w_i at the current level (exact in either precision),
  //                i slowest, node = index(x, y, z)
  //   density, velocity  n and 3 n values as the last step() left them (outputs of step())
  //   viscosity    n per-node nu, or empty in the uniform mode
  // The wall velocity and the force are set by the driver before every step: not state.
  struct State {
    std::vector<double> populations, density, velocity, viscosity;
  };
  void export_state(State& out) const;
  void import_state(State&& in);  // throws std::invalid_argument when a size does not match

 private:
  void update_marked_rates();
  // Populations are stored with padded x-rows (PaddedRows, padded_rows.hpp).
  std::size_t population_index(int i, std::size_t node) const {
    const std::size_t row = node / std::size_t(nx_), x = node % std::size_t(nx_);
    return std::size_t(i) * rows_.per_population() + rows_.index(row, x);
  }
  // Where population i of a node sits now (population_index in the natural state; the AA
  // swapped state after an even in-place step: in_place_stream_collide.hpp).
  std::size_t slot(int i, std::size_t node) const;

  int nx_, ny_, nz_;
  std::size_t n_;
  double nu_;          // uniform viscosity
  double s_nu_;        // its shear rate
  double u_bottom_ = 0.0, u_top_ = 0.0;
  template <class T>
  using Array = std::vector<T, HugePageAllocator<T>>;
  using Field = Array<double>;
  template <class T>
  void step_in();
  template <class T>
  Array<T>& current();
  template <class T>
  Array<T>& next();
  double shifted_population(int i, std::size_t node) const;

  Precision precision_;
  Streaming streaming_;
  CollisionModel collision_ = CollisionModel::mrt;
  bool swapped_ = false;                // in place: after an even step (AA)
  PaddedRows rows_;                     // layout of one population's array
  // Populations f_i - w_i, SoA, padded rows; only the arrays of the precision in use are
  // allocated, the *_next_ ones only for two-lattice streaming.
  Array<double> g64_, g64_next_;
  Array<float> g32_, g32_next_;
  std::vector<unsigned char> macroscopic_rows_;  // ny*nz flags; empty: every row
  Field force_;                         // 3*n
  Field velocity_;                      // 3*n
  Field density_;                       // n
  std::vector<double> node_viscosity_;  // n, empty in the uniform mode
  std::vector<double> node_shear_rate_; // n, s_nu per node
  std::vector<char> marked_;            // n, set since the last step
  std::vector<std::size_t> marked_nodes_;
};

extern template class Fluid<D2Q9>;
extern template class Fluid<D3Q19>;

}  // namespace capsule::lbm
