#pragma once
// The "analysis" block of a campaign (schema in analysis/README.md): which per-member
// fits to make, which tables, the bilinear model, figures on/off. Unknown keys are errors.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace capsule::analysis {

struct TableSpec {
  std::string name;                  // file stem
  std::string x;                     // swept scene parameter
  std::vector<std::string> columns;  // "<fit>.<time>", e.g. "response.k_tau_s"
  std::string normalise = "none";    // "none" | "tau_e" | "tau_v"
};

struct BilinearSpec {
  std::vector<std::string> targets;  // "<fit>.<time>"
  std::optional<double> V_base;      // for eta* (97)
};

struct AnalysisBlock {
  std::vector<std::string> fits{"response", "recovery"};
  std::map<std::string, std::string> parameters;  // name -> JSON pointer into the canonical scene
  std::vector<TableSpec> tables;
  std::optional<BilinearSpec> bilinear;
  bool figures = true;
};

// Every per-member fit name, and the times each one yields.
const std::vector<std::string>& known_fits();
std::vector<std::string> times_of_fit(const std::string& fit);

// Parse and validate; a null block gives the defaults. Throws
// std::invalid_argument("<where>: /analysis/<json path>: <what was expected>").
AnalysisBlock parse_analysis_block(const nlohmann::json& block, const std::string& where);

// Validation only (the `study` planner calls this before running anything).
void validate_analysis_block(const nlohmann::json& block, const std::string& where);

}  // namespace capsule::analysis
