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

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.max_num_iterations = 500;
  // Tight tolerances: the fits are tiny (a few hundred residuals, <= 3 parameters),
  // and the bilinear fit must agree with the closed form to 1e-8.
  options.function_tolerance = 1e-15;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  if (!summary.IsSolutionUsable())
    return FitResult::failure(model, "Ceres failed: " + summary.message);
  for (int i = 0; i < P; ++i)
    if (!std::isfinite(p[i])) return FitResult::failure(model, "Ceres returned a non-finite " + spec.names[i]);
  // A parameter stuck on its bound means the data do not determine it
  // (e.g. a series that does not decay drives k tau to its floor): no number.
  for (int i = 0; i < P; ++i) {
    const double scale = std::max(1.0, std::abs(p[i]));
    // 1e-9 relative: far below any fitted time's resolution, far above round-off.
    if (std::isfinite(spec.lower[i]) && p[i] - spec.lower[i] <= 1e-9 * scale)
      return FitResult::failure(model, spec.names[i] + " ran onto its lower bound: the data do not determine it");
    if (std::isfinite(spec.upper[i]) && spec.upper[i] - p[i] <= 1e-9 * scale)
      return FitResult::failure(model, spec.names[i] + " ran onto its upper bound: the data do not determine it");
  }

  const std::size_t n = points.size();
  const std::size_t dof = n - static_cast<std::size_t>(P);
  const double ss_res = 2.0 * summary.final_cost;  // Ceres' cost is (1/2) sum r^2
  const double s2 = ss_res / static_cast<double>(dof);

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

}  // namespace capsule::analysis::detail
