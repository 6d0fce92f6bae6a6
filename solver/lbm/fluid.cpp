#include "solver/lbm/fluid.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/lbm/equilibrium.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/lbm/stream_collide.hpp"

namespace capsule::lbm {

template <class L>
Fluid<L>::Fluid(int nx, int ny, int nz, double nu)
    : nx_(nx), ny_(ny), nz_(nz), n_(std::size_t(nx) * std::size_t(ny) * std::size_t(nz)), nu_(nu),
      s_nu_(shear_rate_from_viscosity(nu)) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("Fluid: grid sizes must be positive");
  if (L::D == 2 && nz != 1) throw std::invalid_argument("Fluid<D2Q9>: nz must be 1");
  if (!(nu > 0.0)) throw std::invalid_argument("Fluid: viscosity must be positive");
  rows_ = PaddedRows(std::size_t(nx), std::size_t(ny) * std::size_t(nz));
  f_.assign(Q * rows_.per_population(), 0.0);
  f_next_.assign(Q * rows_.per_population(), 0.0);
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
        double feq[Q];
        equilibrium<L>(1.0, v, feq);
        for (int i = 0; i < Q; ++i) f_[population_index(i, node)] = feq[i];
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
void Fluid<L>::step() {
  StreamCollideFields a{nx_, ny_, nz_, n_, rows_, f_.data(), f_next_.data(), force_.data(), velocity_.data(),
                        density_.data(), nullptr, s_nu_, u_bottom_, u_top_};
  if (has_viscosity_field()) {
    update_marked_rates();
    a.shear_rate = node_shear_rate_.data();
    stream_collide<L, true>(a);
  } else {
    stream_collide<L, false>(a);
  }
  f_.swap(f_next_);
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
  double mass = 0.0;
  for (std::size_t node = 0; node < n_; ++node) {
    double m = 0.0;
    for (int i = 0; i < Q; ++i) m += f_[population_index(i, node)];
    mass += m;
  }
  return mass;
}

template <class L>
void Fluid<L>::export_state(State& out) const {
  out.populations.resize(std::size_t(Q) * n_);
  for (int i = 0; i < Q; ++i)
    for (std::size_t node = 0; node < n_; ++node) out.populations[std::size_t(i) * n_ + node] = f_[population_index(i, node)];
  out.density.assign(density_.begin(), density_.end());
  out.velocity.assign(velocity_.begin(), velocity_.end());
  out.viscosity = node_viscosity_;
}

template <class L>
void Fluid<L>::import_state(State&& in) {
  if (in.populations.size() != std::size_t(Q) * n_ || in.density.size() != n_ || in.velocity.size() != 3 * n_ ||
      !(in.viscosity.empty() || in.viscosity.size() == n_))
    throw std::invalid_argument("Fluid::import_state: the saved fields do not fit this lattice");
  for (int i = 0; i < Q; ++i)
    for (std::size_t node = 0; node < n_; ++node) f_[population_index(i, node)] = in.populations[std::size_t(i) * n_ + node];
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
