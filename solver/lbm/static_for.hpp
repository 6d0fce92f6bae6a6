#pragma once
// Compile-time unrolling helpers for the collision kernels.
#include <utility>

namespace capsule::lbm {

// Calls f(std::integral_constant<int, I>) for I = 0 .. N-1, unrolled.
template <int N, class F>
[[gnu::always_inline]] inline void static_for(F&& f) {
  [&]<int... I>(std::integer_sequence<int, I...>) __attribute__((always_inline)) {
    (f(std::integral_constant<int, I>{}), ...);
  }(std::make_integer_sequence<int, N>{});
}

// s += coef * x with coef a compile-time integer (nothing emitted for 0).
template <int coef>
[[gnu::always_inline]] inline void add_term(double& s, double x) {
  if constexpr (coef == 1) s += x;
  else if constexpr (coef == -1) s -= x;
  else if constexpr (coef != 0) s += double(coef) * x;
}

}  // namespace capsule::lbm
