#include "analysis/fit/artificial_viscosity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsule::analysis {

namespace {
// r = x / y with var(r) = r^2 (var x / x^2 + var y / y^2 - 2 cov(x,y) / (x y)) (first-order delta method).
Ratio ratio(const FitResult& fit, std::size_t ix, std::size_t iy) {
  if (!fit.ok || fit.parameters.size() < 2 || fit.covariance.size() < 2)
    throw std::invalid_argument("artificial viscosity: needs a successful bilinear fit");
  const double x = fit.parameters[ix].value, y = fit.parameters[iy].value;
  Ratio r;
  r.value = x / y;
  const double var = r.value * r.value *
                     (fit.covariance[ix][ix] / (x * x) + fit.covariance[iy][iy] / (y * y) -
                      2.0 * fit.covariance[ix][iy] / (x * y));
  r.std_error = std::sqrt(std::max(0.0, var));
  return r;
}
}  // namespace

Ratio ratio_a_over_b(const FitResult& bilinear) { return ratio(bilinear, 0, 1); }
Ratio ratio_b_over_a(const FitResult& bilinear) { return ratio(bilinear, 1, 0); }

double artificial_V(double a_over_b, double V, double eta) { return V + a_over_b * eta; }  // (98)

double artificial_eta(double b_over_a, double V_star, double V) { return b_over_a * (V_star - V); }  // (97)

}  // namespace capsule::analysis
