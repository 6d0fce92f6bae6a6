#pragma once
// The recovery of a cell released after extension, fitted as Hochmuth, Worthy and Evans (1979,
// Biophys. J. 26:101) fit it:
//   (lambda - lambda_inf) / (lambda + lambda_inf) = (lambda_0 - lambda_inf) / (lambda_0 + lambda_inf) exp(-t / t_c),
// lambda = L / W the cell's length over its width (a stretch member's D_axial / D_transverse),
// lambda_0 at the release, lambda_inf at the end of the recovery, t the time since the release;
// their t_c = eta_m / mu, membrane viscosity over shear modulus.
#include <vector>

#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis {

// Fits t_c (parameter "k_t_c", in the member's kt) on [t_stop, t_end]: lambda_0 and lambda_inf are
// the series' values at the rows nearest t_stop and t_end. The fit's fixed inputs hold both, and
// its curve (evaluate_fit) is the left-hand side above.
FitResult fit_extensional_recovery(const std::vector<double>& kt, const std::vector<double>& lambda, double t_stop,
                                   double t_end);

}  // namespace capsule::analysis
