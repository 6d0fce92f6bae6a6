#pragma once
// The recovery of a cell released after extension, fitted as Hochmuth, Worthy and Evans (1979,
// Biophys. J. 26:101) fit it:
//   (lambda - lambda_inf) / (lambda + lambda_inf) = (lambda_0 - lambda_inf) / (lambda_0 + lambda_inf) exp(-t / t_c),
// lambda = L / W the cell's length over its width (a stretch member's D_axial / D_transverse),
// lambda_0 at the release, lambda_inf at the end of the recovery, t the time since the release;
// their t_c = eta_m / mu, membrane viscosity over shear modulus.
#include <limits>
#include <vector>

#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis {

// Fits t_c (parameter "k_t_c", in the member's kt) on [t_stop, t_end]: lambda_0 is the series'
// value at the row nearest t_stop; lambda_inf is `lambda_rest` when it is finite (the shape the
// cell recovers to, known from before the pull), else the value at the row nearest t_end, as
// the paper reads it off the recovered cell (biased by what is left of the recovery at t_end:
// e^-3, 5 % of the amplitude, after 3 t_c). The fit's fixed inputs hold both, and its curve
// (evaluate_fit) is the left-hand side above.
FitResult fit_extensional_recovery(const std::vector<double>& kt, const std::vector<double>& lambda, double t_stop,
                                   double t_end, double lambda_rest = std::numeric_limits<double>::quiet_NaN());

}  // namespace capsule::analysis
