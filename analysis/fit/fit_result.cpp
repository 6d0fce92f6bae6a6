#include "analysis/fit/fit_result.hpp"

#include <cmath>
#include <limits>

namespace capsule::analysis {

namespace {
// JSON has no NaN; a missing number is written as null and read back as NaN.
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }
double number_from(const nlohmann::json& j) {
  return j.is_number() ? j.get<double>() : std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

const FitParameter* FitResult::parameter(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

FitResult FitResult::failure(std::string model, std::string reason) {
  FitResult r;
  r.model = std::move(model);
  r.ok = false;
  r.reason = std::move(reason);
  return r;
}

nlohmann::json to_json(const FitResult& fit) {
  nlohmann::json j;
  j["model"] = fit.model;
  j["ok"] = fit.ok;
  if (!fit.ok) {
    j["reason"] = fit.reason;
    return j;
  }
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : fit.parameters)
    params.push_back({{"name", p.name},
                      {"value", number(p.value)},
                      {"std_error", number(p.std_error)},
                      {"ci95", {number(p.ci_low), number(p.ci_high)}}});
  j["parameters"] = params;
  nlohmann::json cov = nlohmann::json::array();
  for (const auto& row : fit.covariance) {
    nlohmann::json r = nlohmann::json::array();
    for (double x : row) r.push_back(number(x));
    cov.push_back(r);
  }
  j["covariance"] = cov;
  j["n_points"] = fit.n_points;
  j["interval"] = {number(fit.t_begin), number(fit.t_end)};
  j["reduced_chi_square"] = number(fit.reduced_chi_square);
  j["r_squared"] = number(fit.r_squared);
  j["converged"] = fit.converged;
  j["solver_report"] = fit.solver_report;
  j["fixed"] = fit.fixed;
  return j;
}

FitResult fit_result_from_json(const nlohmann::json& j) {
  FitResult r;
  r.model = j.value("model", "");
  r.ok = j.value("ok", false);
  if (!r.ok) {
    r.reason = j.value("reason", "no reason recorded");
    return r;
  }
  for (const auto& p : j.at("parameters")) {
    FitParameter fp;
    fp.name = p.at("name").get<std::string>();
    fp.value = number_from(p.at("value"));
    fp.std_error = number_from(p.at("std_error"));
    fp.ci_low = number_from(p.at("ci95").at(0));
    fp.ci_high = number_from(p.at("ci95").at(1));
    r.parameters.push_back(fp);
  }
  if (j.contains("covariance"))
    for (const auto& row : j.at("covariance")) {
      std::vector<double> v;
      for (const auto& x : row) v.push_back(number_from(x));
      r.covariance.push_back(v);
    }
  r.n_points = j.value("n_points", std::size_t{0});
  if (j.contains("interval")) {
    r.t_begin = number_from(j["interval"].at(0));
    r.t_end = number_from(j["interval"].at(1));
  }
  r.reduced_chi_square = number_from(j.value("reduced_chi_square", nlohmann::json()));
  r.r_squared = number_from(j.value("r_squared", nlohmann::json()));
  r.converged = j.value("converged", false);
  r.solver_report = j.value("solver_report", "");
  r.fixed = j.value("fixed", nlohmann::json::object());
  return r;
}

}  // namespace capsule::analysis
