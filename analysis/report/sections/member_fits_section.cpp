// Per-member fits (85)-(90): the member table, each member's entry in fits.json, and the
// D_xy(kt) figure with its fitted curves (Figs. 13-14, 64).
#include <filesystem>
#include <set>

#include "analysis/fit/exponential_fits.hpp"
#include "analysis/report/figure_declarations.hpp"
#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

Table member_fits_table(const std::vector<MemberAnalysis>& members) {
  Table t;
  t.title = "Per-member fits: fitted k tau with 95 % intervals (Student's t), or why no fit was made";
  t.header = {"case", "member", "fit", "parameter", "value", "std_error", "ci95_low", "ci95_high", "R2",
              "reduced_chi2", "N", "t_begin", "t_end", "converged", "reason"};
  for (const auto* m : ordered(members, "")) {
    for (const auto& key : fit_keys(m->fits)) {
      const FitResult& f = m->fits.at(key);
      if (!f.ok) {
        t.rows.push_back({case_label(m->ref.case_name), m->ref.slug, f.model, "", "", "", "", "", "", "", "", "", "",
                          "", f.reason});
        continue;
      }
      for (const auto& p : f.parameters)
        t.rows.push_back({case_label(m->ref.case_name), m->ref.slug, f.model, p.name, format_number(p.value),
                          format_number(p.std_error), format_number(p.ci_low), format_number(p.ci_high),
                          format_number(f.r_squared), format_number(f.reduced_chi_square), std::to_string(f.n_points),
                          format_number(f.t_begin), format_number(f.t_end), f.converged ? "yes" : "no", ""});
    }
  }
  return t;
}

// A member file under the campaign's results folder (the report folder's parent) is named
// relative to that folder, so shipped results read the same from a clone in any folder;
// one elsewhere keeps the path it was given.
std::string recorded_member_path(const std::string& member_path, const fs::path& report_dir) {
  if (member_path.empty()) return member_path;
  const fs::path root = fs::weakly_canonical(fs::absolute(report_dir)).parent_path();
  const fs::path file = fs::weakly_canonical(fs::absolute(member_path));
  const fs::path rel = file.lexically_relative(root);
  if (rel.empty() || *rel.begin() == "..") return member_path;
  return rel.generic_string();
}

// `extra`: the series besides D_xy that a figure drawing this member with others plots ("theta").
nlohmann::json member_figure(const MemberAnalysis& m, const std::set<std::string>& extra) {
  nlohmann::json mj{{"slug", file_slug(m.ref.slug)}, {"kt", m.kt}, {"D_xy", m.D}, {"curves", nlohmann::json::array()}};
  mj["title"] = case_label(m.ref.case_name) + " / " + m.ref.slug + " (" + m.status + ")";
  if (m.gamma_min.size() == m.kt.size() && m.gamma_max.size() == m.kt.size() && !m.gamma_min.empty())
    mj["gamma"] = {{"min", m.gamma_min}, {"max", m.gamma_max}};
  if (extra.count("theta") && m.theta.size() == m.kt.size()) mj["theta"] = m.theta;
  mj["parameters"] = nlohmann::json::object();  // a figure drawing several members names them by these
  for (const auto& [k, v] : m.parameters)
    if (std::isfinite(v)) mj["parameters"][k] = v;
  mj["markers"] = nlohmann::json::object();
  for (const auto& [k, v] : m.markers)
    if (std::isfinite(v)) mj["markers"][k] = v;
  // A stretch member is drawn as its extension ratio lambda = D_axial / D_transverse (the
  // quantity Hochmuth's recovery fit describes), D_xy of the disc's projection saying little.
  const bool stretch = m.lambda.size() == m.kt.size() && !m.lambda.empty();
  if (stretch) mj["y"] = {{"name", "lambda"}, {"values", m.lambda}};
  for (const auto& key : fit_keys(m.fits)) {
    const FitResult& f = m.fits.at(key);
    if (!f.ok) continue;
    // The extensional fit's curve is (lambda - lambda_inf)/(lambda + lambda_inf): drawn as lambda.
    const bool extensional = key == "extensional_recovery";
    if (extensional != stretch) continue;
    const double lambda_inf = extensional ? f.fixed.value("lambda_inf", k_nan) : k_nan;
    std::vector<double> t, d;
    for (double x : m.kt)
      if (x >= f.t_begin && x <= f.t_end) {
        const double y = evaluate_fit(f, x);
        t.push_back(x);
        d.push_back(extensional ? lambda_inf * (1.0 + y) / (1.0 - y) : y);
      }
    std::string label = f.model;
    nlohmann::json parameters = nlohmann::json::array();  // the figure prints each with its 95 % interval
    for (const auto& p : f.parameters) {
      label += ", " + p.name + " = " + format_number(p.value);
      parameters.push_back({{"name", p.name}, {"value", json_number(p.value)}, {"ci_low", json_number(p.ci_low)},
                            {"ci_high", json_number(p.ci_high)}});
    }
    mj["curves"].push_back({{"label", label}, {"model", f.model}, {"parameters", parameters}, {"kt", t}, {"D", d}});
  }
  return mj;
}

class MemberFitsSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    outputs.fits["members"] = nlohmann::json::array();
    for (const auto& m : context.members) {
      nlohmann::json j{{"id", m.ref.id}, {"slug", m.ref.slug}, {"case", m.ref.case_name},
                       {"path", recorded_member_path(m.ref.path, out_dir)}, {"status", m.status}};
      j["parameters"] = nlohmann::json::object();
      for (const auto& [k, v] : m.parameters) j["parameters"][k] = json_number(v);
      j["fits"] = nlohmann::json::object();
      for (const auto& [k, f] : m.fits) j["fits"][k] = to_json(f);
      outputs.fits["members"].push_back(j);
    }
    outputs.write_table(member_fits_table(context.members), out_dir, "member_fits");
    outputs.figure_data["members"] = nlohmann::json::array();
    const auto extra = together_series(context.request.text_figures);
    for (const auto& m : context.members)
      if (!m.kt.empty() && m.kt.size() == m.D.size()) {
        const auto it = extra.find(file_slug(m.ref.slug));
        outputs.figure_data["members"].push_back(member_figure(m, it == extra.end() ? std::set<std::string>{} : it->second));
      }
  }
};

}  // namespace

std::unique_ptr<ReportSection> member_fits_section() { return std::make_unique<MemberFitsSection>(); }

}  // namespace capsule::analysis
