#pragma once
// How the membrane nodes move with the fluid (20): the time level of the interpolated velocity
// and the order of the position update (scene key resolution.membrane_update,
// 3D only). Per lattice step the fluid is driven by the force F(X^n) spread at X^n (21), then
//
//   euler              X^{n+1} = X^n + U^{n+1}(X^n)                       (the default, (20))
//                      U^{n+1}: the velocity after the fluid step that F(X^n) drove;
//   previous_velocity  X^{n+1} = X^n + U^n(X^n)
//                      U^n: the velocity before that step, the same time level as F(X^n);
//   adams_bashforth2   X^{n+1} = X^n + (3/2) U^{n+1}(X^n) - (1/2) U^n(X^{n-1})
//                      second order in time (the first step is euler).
//
// dt = 1 lattice step, k dt = Re nu / a^2 (about 2e-4 at a = 10, tau = 1.5), so these differ by
// O(k dt) per unit kt; tests/solver/ib/ib_test.cpp checks their order on an exact rotation.
#include <cstddef>
#include <vector>

#include "solver/common/name_table.hpp"

namespace capsule::ib {

enum class MembraneUpdate { euler, previous_velocity, adams_bashforth2 };

inline constexpr NameTable<MembraneUpdate, 3> membrane_update_names{{{MembraneUpdate::euler, "euler"},
                                                                     {MembraneUpdate::previous_velocity, "previous_velocity"},
                                                                     {MembraneUpdate::adams_bashforth2, "adams_bashforth2"}}};
constexpr const auto& name_table(MembraneUpdate) { return membrane_update_names; }

// The second-order Adams-Bashforth position update: X += dt ((3/2) U - (1/2) U_previous), then
// U_previous = U. An empty U_previous (the first step, or the one after a restart point that
// had none) takes the forward Euler step and starts the history.
template <int Dim>
void advance_adams_bashforth2(double* X, const double* U, std::vector<double>& U_previous, std::size_t n,
                              double dt) {
  const std::size_t m = Dim * n;
  if (U_previous.size() != m) {
    for (std::size_t i = 0; i < m; ++i) X[i] += U[i] * dt;
    U_previous.assign(U, U + m);
    return;
  }
  for (std::size_t i = 0; i < m; ++i) {
    X[i] += dt * (1.5 * U[i] - 0.5 * U_previous[i]);
    U_previous[i] = U[i];
  }
}

}  // namespace capsule::ib
