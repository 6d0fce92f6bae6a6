#include "analysis/fit/extensional_recovery.hpp"

#include <cmath>
#include <cstddef>

#include "analysis/fit/exponential_fits.hpp"

namespace capsule::analysis {
namespace {

// The value at the row whose kt is nearest t.
double at_nearest(const std::vector<double>& kt, const std::vector<double>& y, double t) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < kt.size(); ++i)
    if (std::abs(kt[i] - t) < std::abs(kt[best] - t)) best = i;
  return y[best];
}

}  // namespace

FitResult fit_extensional_recovery(const std::vector<double>& kt, const std::vector<double>& lambda, double t_stop,
                                   double t_end, double lambda_rest) {
  const std::string model = "extensional recovery (Hochmuth, Worthy and Evans 1979)";
  if (kt.empty() || kt.size() != lambda.size()) return FitResult::failure(model, "no series, or kt and lambda differ in length");
  const double lambda_0 = at_nearest(kt, lambda, t_stop), lambda_inf = std::isfinite(lambda_rest) ? lambda_rest : at_nearest(kt, lambda, t_end);
  if (!(lambda_inf > 0.0)) return FitResult::failure(model, "lambda_inf is not positive");
  // The left-hand side decays from A to 0 as (86) decays from D_stop: the same fit.
  std::vector<double> y(lambda.size());
  for (std::size_t i = 0; i < lambda.size(); ++i) y[i] = (lambda[i] - lambda_inf) / (lambda[i] + lambda_inf);
  const double A = (lambda_0 - lambda_inf) / (lambda_0 + lambda_inf);
  FitResult fit = fit_recovery(kt, y, A, t_stop, t_end);
  fit.model = model;
  if (fit.ok) fit.parameters.front().name = "k_t_c";
  else fit.reason = model + ": " + fit.reason;
  fit.fixed["lambda_0"] = lambda_0;
  fit.fixed["lambda_inf"] = lambda_inf;
  return fit;
}

}  // namespace capsule::analysis
