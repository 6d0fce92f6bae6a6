#pragma once
// Floating-point precision of the fluid's populations (scene `resolution.precision`).
//  - double: populations stored and collided in double (default);
//  - single: populations stored as float, shifted by the rest equilibrium (f_i - w_i, so the
//    small deviations of a Stokes flow keep their digits), collided in float arithmetic
//    (chosen by measurement: docs/findings/performance.md "Single against double"). rho, u and the force stay double arrays
//    in both, so the immersed-boundary code is the same.
#include "solver/common/name_table.hpp"

namespace capsule::lbm {

enum class Precision { double_precision, single_precision };

inline constexpr NameTable<Precision, 2> precision_names{
    {{Precision::double_precision, "double"}, {Precision::single_precision, "single"}}};
constexpr const auto& name_table(Precision) { return precision_names; }

}  // namespace capsule::lbm
