#include "solver/lbm/fluid.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

#include "solver/lbm/equilibrium.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/lbm/stream_collide.hpp"

namespace capsule::lbm {

template <class L>
Fluid<L>::Fluid(int nx, int ny, int nz, double nu, Precision precision, Streaming streaming)
    : nx_(nx), ny_(ny), nz_(nz), n_(std::size_t(nx) * std::size_t(ny) * std::size_t(nz)), nu_(nu),
      s_nu_(shear_rate_from_viscosity(nu)), precision_(precision), streaming_(streaming) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("Fluid: grid sizes must be positive");
  if (L::D == 2 && nz != 1) throw std::invalid_argument("Fluid<D2Q9>: nz must be 1");
  if (!(nu > 0.0)) throw std::invalid_argument("Fluid: viscosity must be positive");
  rows_ = PaddedRows(std::size_t(nx), std::size_t(ny) * std::size_t(nz));
  const bool two = streaming_ == Streaming::two_lattice;
  if (precision_ == Precision::single_precision) {
    g32_.assign(Q * rows_.per_population(), 0.0f);
    if (two) g32_next_.assign(Q * rows_.per_population(), 0.0f);
  } else {
    g64_.assign(Q * rows_.per_population(), 0.0);
    if (two) g64_next_.assign(Q * rows_.per_population(), 0.0);
  }
  force_.assign(3 * n_, 0.0);
  velocity_.assign(3 * n_, 0.0);
  density_.assign(n_, 1.0);
  initialise_velocity([](double, double, double) { return std::array<double, 3>{0.0, 0.0, 0.0}; });
}

template <class L>
void Fluid<L>::set_wall_velocity(double u_bottom, double u_top) {
  u_bottom_ = u_bottom;
  u_top_ = u_top;
}

template <class L>
void Fluid<L>::initialise_velocity(const std::function<std::array<double, 3>(double, double, double)>& u) {
  for (int z = 0; z < nz_; ++z)
    for (int y = 0; y < ny_; ++y)
      for (int x = 0; x < nx_; ++x) {
        const std::size_t node = index(x, y, z);
        const std::array<double, 3> v = u(x + 0.5, y + 0.5, z + 0.5);
        swapped_ = false;  // written in the natural state
        double feq[Q];
        equilibrium<L>(1.0, v, feq);
        for (int i = 0; i < Q; ++i) {
          const double shifted = feq[i] - double(L::weight_numerator[i]) / double(L::weight_denominator);
          if (precision_ == Precision::single_precision) g32_[population_index(i, node)] = float(shifted);
          else g64_[population_index(i, node)] = shifted;
        }
        density_[node] = 1.0;
        for (int d = 0; d < 3; ++d) velocity_[std::size_t(d) * n_ + node] = d < L::D ? v[d] : 0.0;
      }
}

template <class L>
void Fluid<L>::clear_force() {
  // Only the D components the lattice uses (force(2) of D2Q9 is ignored and stays zero).
  double* F = force_.data();
  const long count = long(L::D) * long(n_);
#pragma omp parallel for schedule(static) if (n_ >= parallel_threshold_nodes)
  for (long i = 0; i < count; ++i) F[i] = 0.0;
}

template <class L>
void Fluid<L>::update_marked_rates() {
  for (std::size_t node : marked_nodes_) {
    node_shear_rate_[node] = shear_rate_from_viscosity(node_viscosity_[node]);
    marked_[node] = 0;
  }
  marked_nodes_.clear();
}

template <class L>
template <class T>
Fluid<L>::Array<T>& Fluid<L>::current() {
  if constexpr (std::is_same_v<T, float>) return g32_;
  else return g64_;
}

template <class L>
template <class T>
Fluid<L>::Array<T>& Fluid<L>::next() {
  if constexpr (std::is_same_v<T, float>) return g32_next_;
  else return g64_next_;
}

// Single precision collides in float: measured faster than double arithmetic on float
// storage (docs/findings/performance.md "Single against double") and, on shifted populations, as accurate as the tests ask.
template <class L>
template <class T>
void Fluid<L>::step_in() {
  Array<T>& g = current<T>();
  if (has_viscosity_field()) update_marked_rates();
  const double* rates = has_viscosity_field() ? node_shear_rate_.data() : nullptr;
  const unsigned char* macro = macroscopic_rows_.empty() ? nullptr : macroscopic_rows_.data();
  const bool trt = collision_ == CollisionModel::trt;
  if (streaming_ == Streaming::in_place) {
    InPlaceFields<T> a{nx_, ny_, nz_, n_, rows_, g.data(), force_.data(), velocity_.data(), density_.data(),
                       rates, macro, s_nu_, u_bottom_, u_top_};
    stream_collide_pass<L, T>(a, swapped_, rates != nullptr, trt);
    swapped_ = !swapped_;
    return;
  }
  Array<T>& g_next = next<T>();
  ShiftedFields<T> a{nx_, ny_, nz_, n_, rows_, g.data(), g_next.data(), force_.data(), velocity_.data(),
                     density_.data(), rates, macro, s_nu_, u_bottom_, u_top_};
  stream_collide_pass<L, T>(a, rates != nullptr, trt);
  g.swap(g_next);
}

template <class L>
void Fluid<L>::step() {
  if (precision_ == Precision::single_precision) step_in<float>();
  else step_in<double>();
}

template <class L>
void Fluid<L>::set_macroscopic_region(const std::vector<RowBox>& boxes) {
  macroscopic_rows_.assign(std::size_t(ny_) * std::size_t(nz_), 0);
  for (const RowBox& b : boxes) {
    const int y0 = std::max(b.y_begin, 0), y1 = std::min(b.y_end, ny_);
    const int zcount = std::min(b.z_end - b.z_begin, nz_);
    for (int dz = 0; dz < zcount; ++dz) {
      const int z = ((b.z_begin + dz) % nz_ + nz_) % nz_;
      for (int y = y0; y < y1; ++y) macroscopic_rows_[std::size_t(y) + std::size_t(ny_) * std::size_t(z)] = 1;
    }
  }
}

template <class L>
void Fluid<L>::set_macroscopic_everywhere() {
  macroscopic_rows_.clear();
}

template <class L>
double Fluid<L>::macroscopic_fraction() const {
  if (macroscopic_rows_.empty()) return 1.0;
  std::size_t on = 0;
  for (unsigned char f : macroscopic_rows_) on += f;
  return double(on) / double(macroscopic_rows_.size());
}

template <class L>
double Fluid<L>::population(int i, std::size_t node) const {
  return double(L::weight_numerator[i]) / double(L::weight_denominator) + shifted_population(i, node);
}

template <class L>
std::array<double, 4> Fluid<L>::moments(std::size_t node) const {
  // shifted populations f_i - w_i: the weights sum to one and have no first moment
  double drho = 0.0, j[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < Q; ++i) {
    const double g = shifted_population(i, node);
    drho += g;
    for (int a = 0; a < D; ++a) j[a] += L::c[i][a] * g;
  }
  return {1.0 + drho, j[0], j[1], j[2]};
}

template <class L>
std::size_t Fluid<L>::slot(int i, std::size_t node) const {
  if (!swapped_) return population_index(i, node);
  // AA swapped state: f_i(x) sits in A[opp(i)][x - c_i], or in A[i][x] when x - c_i is
  // beyond a wall (the bounced population).
  using B = MomentBasis<L>;
  const int x = int(node % std::size_t(nx_)), y = int((node / std::size_t(nx_)) % std::size_t(ny_));
  const int z = int(node / (std::size_t(nx_) * std::size_t(ny_)));
  const int ys = y - L::c[i][1];
  if (ys < 0 || ys >= ny_) return population_index(i, node);
  const int xs = (x - L::c[i][0] + nx_) % nx_, zs = (z - L::c[i][2] + nz_) % nz_;
  return population_index(B::opposite[i], index(xs, ys, zs));
}

template <class L>
double Fluid<L>::shifted_population(int i, std::size_t node) const {
  const std::size_t k = slot(i, node);
  return precision_ == Precision::single_precision ? double(g32_[k]) : g64_[k];
}

template <class L>
void Fluid<L>::set_viscosity(std::size_t node, double nu) {
  if (!(nu > 0.0)) throw std::invalid_argument("Fluid::set_viscosity: viscosity must be positive");
  if (!has_viscosity_field()) {
    node_viscosity_.assign(n_, nu_);
    node_shear_rate_.assign(n_, s_nu_);
    marked_.assign(n_, 0);
    marked_nodes_.clear();
  }
  if (node_viscosity_[node] == nu) return;  // unchanged: nothing to recompute
  node_viscosity_[node] = nu;
  if (!marked_[node]) {
    marked_[node] = 1;
    marked_nodes_.push_back(node);
  }
}

template <class L>
void Fluid<L>::set_uniform_viscosity(double nu) {
  if (!(nu > 0.0)) throw std::invalid_argument("Fluid::set_uniform_viscosity: viscosity must be positive");
  nu_ = nu;
  s_nu_ = shear_rate_from_viscosity(nu);
  node_viscosity_ = {};
  node_shear_rate_ = {};
  marked_ = {};
  marked_nodes_.clear();
}

template <class L>
double Fluid<L>::viscosity(std::size_t node) const {
  return has_viscosity_field() ? node_viscosity_[node] : nu_;
}

template <class L>
double Fluid<L>::total_mass() const {
  // rho = 1 + sum of the shifted populations: sum the deviations, then add the node count.
  double excess = 0.0;
  for (std::size_t node = 0; node < n_; ++node) {
    double m = 0.0;
    for (int i = 0; i < Q; ++i) m += shifted_population(i, node);
    excess += m;
  }
  return double(n_) + excess;
}

template <class L>
void Fluid<L>::export_state(State& out) const {
  // The shifted populations f_i - w_i, exact in either precision (a float is a double exactly).
  out.populations.resize(std::size_t(Q) * n_);
  for (int i = 0; i < Q; ++i)
    for (std::size_t node = 0; node < n_; ++node) out.populations[std::size_t(i) * n_ + node] = shifted_population(i, node);
  out.density.assign(density_.begin(), density_.end());
  out.velocity.assign(velocity_.begin(), velocity_.end());
  out.viscosity = node_viscosity_;
}

template <class L>
void Fluid<L>::import_state(State&& in) {
  if (in.populations.size() != std::size_t(Q) * n_ || in.density.size() != n_ || in.velocity.size() != 3 * n_ ||
      !(in.viscosity.empty() || in.viscosity.size() == n_))
    throw std::invalid_argument("Fluid::import_state: the saved fields do not fit this lattice");
  // Back into the natural (unswapped) layout: the in-place and two-lattice schemes give the
  // same numbers from the same populations (tests/solver/lbm), so the next step continues bitwise.
  swapped_ = false;
  for (int i = 0; i < Q; ++i)
    for (std::size_t node = 0; node < n_; ++node) {
      const double g = in.populations[std::size_t(i) * n_ + node];
      if (precision_ == Precision::single_precision) current<float>()[population_index(i, node)] = static_cast<float>(g);
      else current<double>()[population_index(i, node)] = g;
    }
  std::copy(in.density.begin(), in.density.end(), density_.begin());
  std::copy(in.velocity.begin(), in.velocity.end(), velocity_.begin());
  if (in.viscosity.empty()) {
    set_uniform_viscosity(nu_);
  } else {
    // Every rate follows from its node's viscosity alone (as update_marked_rates() computes it).
    node_viscosity_ = std::move(in.viscosity);
    node_shear_rate_.resize(n_);
    for (std::size_t node = 0; node < n_; ++node) node_shear_rate_[node] = shear_rate_from_viscosity(node_viscosity_[node]);
    marked_.assign(n_, 0);
    marked_nodes_.clear();
  }
}

template class Fluid<D2Q9>;
template class Fluid<D3Q19>;

}  // namespace capsule::lbm
