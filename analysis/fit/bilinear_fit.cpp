#include "analysis/fit/bilinear_fit.hpp"

#include <cmath>
#include <string>

#include "analysis/fit/ceres_least_squares.hpp"

namespace capsule::analysis {

namespace {
struct BilinearResidual {
  double eta, V, y;
  template <class T>
  bool operator()(const T* p, T* r) const {
    r[0] = p[0] * T(eta) + p[1] * T(V) + p[2] - T(y);  // (95)/(96)
    return true;
  }
};
}  // namespace

FitResult fit_bilinear(const std::vector<double>& eta, const std::vector<double>& V,
                       const std::vector<double>& k_tau) {
  const std::string model = "bilinear (95)-(96)";
  if (eta.size() != V.size() || V.size() != k_tau.size())
    return FitResult::failure(model, "eta, V and k tau differ in length");
  std::vector<BilinearResidual> points;
  std::vector<double> y;
  for (std::size_t i = 0; i < eta.size(); ++i) {
    if (!std::isfinite(eta[i]) || !std::isfinite(V[i]) || !std::isfinite(k_tau[i]))
      return FitResult::failure(model, "non-finite input at member " + std::to_string(i));
    points.push_back({eta[i], V[i], k_tau[i]});
    y.push_back(k_tau[i]);
  }
  if (points.size() < k_min_bilinear_points)
    return FitResult::failure(model, "too few members (" + std::to_string(points.size()) + " < " +
                                         std::to_string(k_min_bilinear_points) + ")");
  // Start from the mean as intercept; the problem is linear, so one Gauss-Newton step solves it.
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  const double inf = detail::k_unbounded;
  detail::ParameterSpec<3> spec{{"a", "b", "c"}, {0.0, 0.0, mean}, {-inf, -inf, -inf}, {inf, inf, inf}};
  return detail::solve_least_squares<3>(model, points, y, spec, std::nan(""), std::nan(""));
}

}  // namespace capsule::analysis
