#pragma once
// Goodness-of-fit and interval statistics shared by every fit.
#include <cstddef>
#include <vector>

namespace capsule::analysis {

// Two-sided 95 % quantile of Student's t with `dof` degrees of freedom (boost::math).
double student_t_975(std::size_t dof);

// R^2 = 1 - SS_res / SS_tot about the mean of y. NaN when SS_tot = 0.
double r_squared(const std::vector<double>& y, double ss_res);

// Sum of squared deviations of y about its mean.
double total_sum_of_squares(const std::vector<double>& y);

}  // namespace capsule::analysis
