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
  std::string normalise = "none";    // "none" | "tau_e" | "tau_v" | "seconds"
};

struct BilinearSpec {
  std::vector<std::string> targets;  // "<fit>.<time>"
  std::optional<double> V_base;      // for eta* (97)
  // A resolution ladder of the whole (eta, V) grid: with `ladder` (a dotted scene key, e.g.
  // "resolution.a") the model is fitted per case and per value of that key, and each
  // coefficient is extrapolated over the levels (Richardson, richardson.hpp).
  std::string ladder;                // "" = one fit per case
  std::string spacing;               // h from the key's value x: "1/x", "2^-x" or "x"
  double assumed_order = 1.0;        // order taken for a two-level ladder
};

// A resolution ladder (analysis/README.md "Resolution ladder, accuracy against cost, stability"): members that differ only in `key`.
struct LadderSpec {
  std::string name;                     // file stem under ladder/; default "ladder_<last part of key>"
  std::string key;                      // dotted scene key, e.g. "resolution.a"
  std::string spacing;                  // h from the key's value x: "1/x", "2^-x" or "x"
  std::vector<std::string> quantities;  // default_quantities() when not given
  std::vector<std::string> cases;       // only members of these cases (empty: all)
  double assumed_order = 1.0;           // order taken for a two-level ladder (first order in 1/a, docs/guide/model.md "Immersed boundary kernel")
};

// A reference value for the accuracy table: given numbers, or a ladder's extrapolation.
struct ReferenceSpec {
  std::string case_name;                  // "" = every case
  std::map<std::string, double> values;   // quantity -> reference value
  std::string ladder;                     // name of a ladder of the block ("" = none)
};

struct AccuracySpec {
  std::vector<std::string> quantities;    // default_quantities() when not given
  std::vector<std::string> settings;      // dotted scene keys that make the "setting"
  std::vector<ReferenceSpec> reference;
  std::vector<double> bounds{0.01, 0.02, 0.05};  // relative errors for "cheapest within"
};

struct StabilitySpec {
  std::vector<std::string> parameters;    // swept scene parameters (names as in tables[].x)
};

// A published curve D(kt) (published_curves.hpp) and the members it is compared with.
struct PublishedSpec {
  std::string curve;                     // embedded curve name (published_curve_names())
  std::string case_name;                 // "" = members of any case
  std::map<std::string, double> where;   // scene parameter (as tables[].x) -> the member's value
};

// One measured quantity of an experiment and the member series compared with it.
struct ExperimentQuantity {
  std::string measured;  // the data's column of means
  std::string spread;    // the data's column of standard deviations
  std::string series;    // the member series, read where the member's first phase ended (t_stop)
};

// An experiment's data (experiment_data.hpp) and the members that reproduce it: one member per
// data point (and per value of `group`), its scene parameter `parameter` equal to the data's `x`.
struct ExperimentSpec {
  std::string data;       // embedded data name (experiment_data_names())
  std::string x;          // the data's column of the controlled variable, e.g. "force_pN"
  std::string parameter;  // the scene parameter holding it (dotted, as tables[].x)
  std::string group;      // scene parameter telling apart members at one x (a resolution); "" none
  std::vector<ExperimentQuantity> compare;
};

struct AnalysisBlock {
  std::vector<std::string> fits{"response", "recovery"};
  std::map<std::string, std::string> parameters;  // name -> JSON pointer into the canonical scene
  std::vector<TableSpec> tables;
  std::optional<BilinearSpec> bilinear;
  std::vector<LadderSpec> ladders;
  std::optional<AccuracySpec> accuracy;
  std::optional<StabilitySpec> stability;
  std::vector<PublishedSpec> published;
  std::vector<ExperimentSpec> experiments;
  bool figures = true;
};

// Member quantities the ladder and accuracy analyses compare: "<fit>.<time>" of a listed
// fit, or a marker: "D_stop" (D_xy when the shear stopped: the steady D_xy of a shear to
// steady state), "D_max", "D_inf".
const std::vector<std::string>& marker_quantities();
// D_stop and every time of the block's fits.
std::vector<std::string> default_quantities(const std::vector<std::string>& fits);
// The setting keys an accuracy block compares by default.
const std::vector<std::string>& default_setting_keys();

// Every per-member fit name, and the times each one yields.
const std::vector<std::string>& known_fits();
std::vector<std::string> times_of_fit(const std::string& fit);

// Parse and validate; a null block gives the defaults. Throws
// std::invalid_argument("<where>: /analysis/<json path>: <what was expected>").
AnalysisBlock parse_analysis_block(const nlohmann::json& block, const std::string& where);

// Validation only (the `study` planner calls this before running anything).
void validate_analysis_block(const nlohmann::json& block, const std::string& where);

}  // namespace capsule::analysis
