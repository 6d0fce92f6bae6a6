#pragma once
// The outcome of one least-squares fit: parameters with standard errors and
// 95 % intervals, goodness of fit, and the data it was made on -- or, when the
// fit could not be made, only the reason (analysis/README.md "What each fit fits").
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace capsule::analysis {

struct FitParameter {
  std::string name;       // e.g. "k_tau_s"
  double value = 0.0;
  double std_error = 0.0; // sqrt of the covariance diagonal scaled by s^2
  double ci_low = 0.0;    // 95 % interval, Student's t with N - p degrees of freedom
  double ci_high = 0.0;
  double half_width() const { return 0.5 * (ci_high - ci_low); }
};

struct FitResult {
  std::string model;          // "response (85)", ...
  bool ok = false;            // false: `reason` says why, and no number is meaningful
  std::string reason;
  std::vector<FitParameter> parameters;
  std::vector<std::vector<double>> covariance;  // p x p, scaled by s^2
  std::size_t n_points = 0;
  double t_begin = 0.0;       // interval fitted, in the member's kt
  double t_end = 0.0;
  double reduced_chi_square = 0.0;  // = s^2 = 2 cost / (N - p): the data carry no error bars
  double r_squared = 0.0;     // 1 - SS_res / SS_tot
  bool converged = false;     // Ceres reported a usable, converged solution
  std::string solver_report;  // Ceres' one-line summary
  // Fixed inputs taken from markers (D_max, D_stop, ...), kept for plotting the curve.
  nlohmann::json fixed = nlohmann::json::object();

  const FitParameter* parameter(const std::string& name) const;
  static FitResult failure(std::string model, std::string reason);
};

nlohmann::json to_json(const FitResult& fit);
FitResult fit_result_from_json(const nlohmann::json& j);

}  // namespace capsule::analysis
