#pragma once
// Floating-point precision of the fluid's populations (scene `resolution.precision`).
//  - double: populations stored and collided in double (default);
//  - single: populations stored as float, shifted by the rest equilibrium (f_i - w_i, so the
//    small deviations of a Stokes flow keep their digits), collided in float arithmetic
//    (chosen by measurement: docs/findings/performance.md "Single against double"). rho, u and the force stay double arrays
//    in both, so the immersed-boundary code is the same.
#include <stdexcept>
#include <string>

namespace capsule::lbm {

enum class Precision { double_precision, single_precision };

inline const char* precision_name(Precision p) { return p == Precision::single_precision ? "single" : "double"; }

inline Precision precision_from_name(const std::string& name) {
  if (name == "double") return Precision::double_precision;
  if (name == "single") return Precision::single_precision;
  throw std::invalid_argument("precision must be \"double\" or \"single\", got \"" + name + "\"");
}

}  // namespace capsule::lbm
