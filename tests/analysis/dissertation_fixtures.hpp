#pragma once
// Test helper: a synthetic results folder for THESIS.md -- fits.json files written by hand
// with known fitted times and bilinear coefficients, laid out as study writes them
// (<dir>/<campaign>/report/fits.json), so the comparison's verdicts can be checked exactly.
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/dissertation/claims.hpp"
#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis::testing {

// A successful fit with the given parameters (value, 95 % half-width) and R^2.
inline FitResult known_fit(const std::string& model, const std::vector<std::pair<std::string, std::pair<double, double>>>& params,
                           double r2 = 0.999, std::size_t n = 20) {
  FitResult f;
  f.model = model;
  f.ok = true;
  f.converged = true;
  f.r_squared = r2;
  f.n_points = n;
  for (const auto& [name, v] : params) {
    FitParameter p;
    p.name = name;
    p.value = v.first;
    p.std_error = v.second / 2.0;
    p.ci_low = v.first - v.second;
    p.ci_high = v.first + v.second;
    f.parameters.push_back(p);
  }
  return f;
}

inline nlohmann::json member_json(const std::string& slug, const std::string& case_name,
                                  const std::map<std::string, double>& parameters,
                                  const std::map<std::string, FitResult>& fits, const std::string& path = "") {
  nlohmann::json j{{"id", "id-" + slug}, {"slug", slug}, {"case", case_name}, {"path", path}, {"status", "complete"}};
  j["parameters"] = parameters;
  j["fits"] = nlohmann::json::object();
  for (const auto& [k, f] : fits) j["fits"][k] = to_json(f);
  return j;
}

inline nlohmann::json bilinear_json(const std::string& target, double Ca, double E_b, const FitResult& fit) {
  return {{"case", ""}, {"target", target}, {"Ca", Ca}, {"E_b", E_b}, {"fit", to_json(fit)},
          {"members", nlohmann::json::array()}, {"excluded", nlohmann::json::array()}};
}

inline void write_fits(const std::filesystem::path& results, const std::string& campaign,
                       const nlohmann::json& members, const nlohmann::json& bilinear = nlohmann::json::array(),
                       const nlohmann::json& analysis = nlohmann::json()) {
  const auto dir = results / campaign / "report";
  std::filesystem::create_directories(dir);
  nlohmann::json j{{"campaign", campaign}, {"members", members}, {"bilinear", bilinear}};
  if (!analysis.is_null()) j["analysis"] = analysis;
  std::ofstream(dir / "fits.json") << j.dump(2);
}

// The claim of `section` whose statement contains `words`; throws (failing the test) when there is
// none. Keep the claims vector alive while the reference is used.
inline const ClaimResult& find_claim(const std::vector<ClaimResult>& claims, const std::string& section,
                                     const std::string& words) {
  for (const auto& c : claims)
    if (c.section == section && c.statement.find(words) != std::string::npos) return c;
  throw std::runtime_error("no claim " + section + " containing \"" + words + "\"");
}

}  // namespace capsule::analysis::testing
