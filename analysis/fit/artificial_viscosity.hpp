#pragma once
// Artificial viscosity maps of Sec. 5.1.2 from a bilinear fit's a and b, with the
// delta-method standard error of the ratio (using the fit's covariance of a and b).
#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis {

struct Ratio {
  double value = 0.0;
  double std_error = 0.0;
};

// a / b and b / a of a successful bilinear fit (parameters "a", "b").
Ratio ratio_a_over_b(const FitResult& bilinear);
Ratio ratio_b_over_a(const FitResult& bilinear);

// (98) V* = V + (a / b) eta: the fluid viscosity ratio an elastic capsule needs to
// respond like a capsule with fluid ratio V and membrane ratio eta.
double artificial_V(double a_over_b, double V, double eta);

// (97) eta = (b / a)(V* - V): the membrane viscosity ratio equivalent to raising the
// fluid viscosity ratio from V to V*.
double artificial_eta(double b_over_a, double V_star, double V);

}  // namespace capsule::analysis
