#include "analysis/fit/fit_statistics.hpp"

#include <limits>
#include <numeric>

#include <boost/math/distributions/students_t.hpp>

namespace capsule::analysis {

double student_t_975(std::size_t dof) {
  if (dof == 0) return std::numeric_limits<double>::quiet_NaN();
  boost::math::students_t dist(static_cast<double>(dof));
  return boost::math::quantile(dist, 0.975);
}

double total_sum_of_squares(const std::vector<double>& y) {
  if (y.empty()) return 0.0;
  const double mean = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
  double ss = 0.0;
  for (double v : y) ss += (v - mean) * (v - mean);
  return ss;
}

double r_squared(const std::vector<double>& y, double ss_res) {
  const double ss_tot = total_sum_of_squares(y);
  if (!(ss_tot > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return 1.0 - ss_res / ss_tot;
}

}  // namespace capsule::analysis
