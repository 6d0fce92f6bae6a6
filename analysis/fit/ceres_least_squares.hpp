#pragma once
// Internal to the analyser (included only by the fitting .cpp files, to keep the
// number of translation units that compile Ceres small): one bounded least-squares
// solve with Ceres and the statistics every fit reports.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <ceres/ceres.h>

#include "analysis/fit/fit_result.hpp"
#include "analysis/fit/fit_statistics.hpp"

namespace capsule::analysis::detail {

inline constexpr double k_unbounded = std::numeric_limits<double>::infinity();

template <int P>
struct ParameterSpec {
  std::array<std::string, P> names;
  std::array<double, P> initial;
  std::array<double, P> lower;  // -k_unbounded: no bound
  std::array<double, P> upper;  // +k_unbounded: no bound
};

// Dense QR with tight tolerances: the fits are tiny (a few hundred residuals, <= 3 parameters),
// and the bilinear fit must agree with the closed form to 1e-8.
inline ceres::Solver::Options fit_solver_options() {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.max_num_iterations = 500;
  options.function_tolerance = 1e-15;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;
  return options;
}

// Why the solution gives no number ("" when it does): a non-finite parameter, or one stuck on its
// bound, which the data do not determine (e.g. a series that does not decay drives k tau to its floor).
template <int P>
std::string undetermined_parameter(const std::array<double, P>& p, const ParameterSpec<P>& spec) {
  for (int i = 0; i < P; ++i)
    if (!std::isfinite(p[i])) return "Ceres returned a non-finite " + spec.names[i];
  for (int i = 0; i < P; ++i) {
    const double scale = std::max(1.0, std::abs(p[i]));
    // 1e-9 relative: far below any fitted time's resolution, far above round-off.
    if (std::isfinite(spec.lower[i]) && p[i] - spec.lower[i] <= 1e-9 * scale)
      return spec.names[i] + " ran onto its lower bound: the data do not determine it";
    if (std::isfinite(spec.upper[i]) && spec.upper[i] - p[i] <= 1e-9 * scale)
      return spec.names[i] + " ran onto its upper bound: the data do not determine it";
  }
  return "";
}

// The fitted parameters with their standard errors and 95 % intervals (Student's t with n - P
// degrees of freedom) from `cov`, the row-major (J^T J)^-1, scaled by the residual variance.
template <int P>
FitResult fit_with_intervals(const std::string& model, const std::array<double, P>& p, const std::array<double, P * P>& cov,
                             const ceres::Solver::Summary& summary, std::size_t n, const std::vector<double>& y,
                             const ParameterSpec<P>& spec, double t_begin, double t_end) {
  const std::size_t dof = n - static_cast<std::size_t>(P);
  const double ss_res = 2.0 * summary.final_cost;  // Ceres' cost is (1/2) sum r^2
  const double s2 = ss_res / static_cast<double>(dof);
  FitResult fit;
  fit.model = model;
  fit.ok = true;
  fit.n_points = n;
  fit.t_begin = t_begin;
  fit.t_end = t_end;
  fit.reduced_chi_square = s2;
  fit.r_squared = r_squared(y, ss_res);
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  fit.solver_report = summary.BriefReport();
  const double t975 = student_t_975(dof);
  fit.covariance.assign(P, std::vector<double>(P, 0.0));
  for (int i = 0; i < P; ++i) {
    for (int j = 0; j < P; ++j) fit.covariance[i][j] = s2 * cov[i * P + j];
    FitParameter fp;
    fp.name = spec.names[i];
    fp.value = p[i];
    fp.std_error = std::sqrt(std::max(0.0, fit.covariance[i][i]));
    fp.ci_low = p[i] - t975 * fp.std_error;
    fp.ci_high = p[i] + t975 * fp.std_error;
    fit.parameters.push_back(fp);
  }
  return fit;
}

// `points[i]` is a functor with `template <class T> bool operator()(const T* p, T* r) const`
// writing the single residual model(p) - y_i; `y` are the observations (for R^2).
template <int P, class Functor>
FitResult solve_least_squares(const std::string& model, const std::vector<Functor>& points,
                              const std::vector<double>& y, const ParameterSpec<P>& spec,
                              double t_begin, double t_end) {
  std::array<double, P> p = spec.initial;
  ceres::Problem problem;
  for (const auto& f : points)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Functor, 1, P>(new Functor(f)), nullptr,
                             p.data());
  for (int i = 0; i < P; ++i) {
    if (std::isfinite(spec.lower[i])) problem.SetParameterLowerBound(p.data(), i, spec.lower[i]);
    if (std::isfinite(spec.upper[i])) problem.SetParameterUpperBound(p.data(), i, spec.upper[i]);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(fit_solver_options(), &problem, &summary);
  if (!summary.IsSolutionUsable())
    return FitResult::failure(model, "Ceres failed: " + summary.message);
  if (const std::string why = undetermined_parameter<P>(p, spec); !why.empty()) return FitResult::failure(model, why);

  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::DENSE_SVD;  // reports rank deficiency instead of aborting
  cov_options.num_threads = 1;
  ceres::Covariance covariance(cov_options);
  std::vector<std::pair<const double*, const double*>> blocks{{p.data(), p.data()}};
  if (!covariance.Compute(blocks, &problem))
    return FitResult::failure(model, "covariance not computable: the Jacobian is rank deficient "
                                     "(the parameters are not separately determined by these data)");
  std::array<double, P * P> cov{};
  covariance.GetCovarianceBlock(p.data(), p.data(), cov.data());  // row-major (J^T J)^-1
  return fit_with_intervals<P>(model, p, cov, summary, points.size(), y, spec, t_begin, t_end);
}

}  // namespace capsule::analysis::detail
