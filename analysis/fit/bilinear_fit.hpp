#pragma once
// Bilinear viscosity model (95)/(96): k tau = a eta + b V + c, fitted over the
// members of a campaign (Sec. 5.1.1, Table 2).
#include <vector>

#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis {

// Fewer members than this give no fit: 3 coefficients need >= 2 residual degrees of
// freedom for a variance estimate that is not a single squared residual.
inline constexpr std::size_t k_min_bilinear_points = 5;

// Parameters "a", "b", "c" in that order. Unbounded: the text's coefficients are
// positive, but a negative fitted slope is a finding to report, not to clip.
FitResult fit_bilinear(const std::vector<double>& eta, const std::vector<double>& V,
                       const std::vector<double>& k_tau);

}  // namespace capsule::analysis
