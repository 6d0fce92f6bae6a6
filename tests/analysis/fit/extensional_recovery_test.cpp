// The Hochmuth-Worthy-Evans recovery fit (analysis/fit/extensional_recovery.hpp) on a synthetic
// recovery with a known t_c.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "analysis/fit/extensional_recovery.hpp"

using namespace capsule::analysis;

namespace {
// lambda(t) of the model: y = A exp(-(t - t_stop) / t_c), lambda = lambda_inf (1 + y) / (1 - y);
// before the release a held extension lambda_0, which the fit must leave out.
struct Recovery {
  std::vector<double> kt, lambda;
};
Recovery synthetic(double lambda_0, double lambda_inf, double t_c, double t_stop, double t_end, double dt) {
  const double A = (lambda_0 - lambda_inf) / (lambda_0 + lambda_inf);
  Recovery r;
  for (double t = 0; t <= t_end + 1e-9; t += dt) {
    const double y = t < t_stop ? A : A * std::exp(-(t - t_stop) / t_c);
    r.kt.push_back(t);
    r.lambda.push_back(lambda_inf * (1 + y) / (1 - y));
  }
  return r;
}
}  // namespace

TEST_CASE("the extensional recovery fit returns the t_c of a synthetic recovery", "[fit][stretch]") {
  // 12 t_c of recovery: lambda(t_end) is lambda_inf to 1e-6, which bounds the bias of taking it as lambda_inf.
  const Recovery r = synthetic(2.2, 1.05, 0.7, 3.0, 3.0 + 12 * 0.7, 0.05);
  const FitResult fit = fit_extensional_recovery(r.kt, r.lambda, 3.0, 3.0 + 12 * 0.7);
  REQUIRE(fit.ok);
  CHECK(fit.parameter("k_t_c")->value == Approx(0.7).epsilon(1e-4));
  CHECK(fit.r_squared > 0.999999);
  CHECK(fit.fixed["lambda_0"].get<double>() == Approx(2.2));
  CHECK(fit.fixed["lambda_inf"].get<double>() == Approx(1.05).epsilon(1e-5));
}

TEST_CASE("the extensional recovery fit refuses a recovery too short to fit", "[fit][stretch]") {
  const Recovery r = synthetic(2.2, 1.05, 0.7, 3.0, 3.1, 0.05);
  const FitResult fit = fit_extensional_recovery(r.kt, r.lambda, 3.0, 3.1);
  CHECK(!fit.ok);
  CHECK(fit.reason.find("too few points") != std::string::npos);
  CHECK(!fit_extensional_recovery({}, {}, 0, 1).ok);
}
