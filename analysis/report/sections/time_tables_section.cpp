// Characteristic-time tables (Figs. 15-20, 25-28, 33-36): the block's "tables", each a
// fitted time against one swept parameter, optionally normalised by tau_e or tau_v.
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

// Normalisation factor of a time for a member: k tau / (Ca V) (tau_e), k tau / (Ca eta) (tau_v),
// or k (seconds: tau in s for a cell given in physical units, docs/guide/physical_units.md).
double normaliser(const MemberAnalysis& m, const std::string& normalise, std::string& why) {
  if (normalise == "none") return 1.0;
  if (normalise == "seconds") {
    const nlohmann::json* physical =
        m.scene.is_object() && m.scene.contains("physical") ? &m.scene["physical"] : nullptr;
    if (!physical || !physical->contains("shear_rate_per_s") || !(*physical)["shear_rate_per_s"].is_number()) {
      why = "no time in seconds: the scene gives no cell in physical units";
      return k_nan;
    }
    return (*physical)["shear_rate_per_s"].get<double>();
  }
  const std::string other = normalise == "tau_e" ? "V" : "eta";
  for (const std::string& name : {std::string("Ca"), other})
    if (m.missing.count(name)) {
      why = m.missing.at(name);
      return k_nan;
    }
  const double d = parameter(m, "Ca") * parameter(m, other);
  if (!(d > 0.0)) {
    why = normalise + " undefined: Ca " + other + " = 0";
    return k_nan;
  }
  return d;
}

struct TableSeries {  // for the figure of a table
  std::vector<double> x, y, lo, hi;
};

Table time_table(const TableSpec& spec, const std::vector<MemberAnalysis>& members, const std::set<std::string>& ladder_keys,
                 std::map<std::string, std::map<std::string, TableSeries>>& series) {
  Table t;
  const std::string unit = spec.normalise == "tau_e"     ? "tau / tau_e = k tau / (Ca V)"
                           : spec.normalise == "tau_v"   ? "tau / tau_v = k tau / (Ca eta)"
                           : spec.normalise == "seconds" ? "tau in seconds = k tau / k"
                                                         : "k tau";
  t.title = spec.name + ": " + unit + " against " + spec.x + " (95 % intervals, Student's t)";
  t.header = {"case", spec.x, "member"};
  for (const auto& c : spec.columns) {
    t.header.push_back(c);
    t.header.push_back(c + " ±95%");
    t.header.push_back(c + " R2");
  }
  // Figure lines: one per case and per value of any other standard parameter that
  // varies within the case independently of x (e.g. V on an (eta, V) grid, not eta where x is the
  // membrane viscosity in physical units that sets it) and per resolution (a ladder's levels, or
  // resolution.a swept: a = 5 and a = 7 are separate markers), so no line joins unlike members.
  std::set<std::string> splitting{"Ca", "E_b", "V", "eta", "resolution.a"};
  splitting.insert(ladder_keys.begin(), ladder_keys.end());
  std::map<std::string, std::set<std::string>> varying;  // case -> parameter names
  for (const std::string& name : splitting) {
    if (name == spec.x) continue;
    std::map<std::string, std::set<double>> values;
    std::map<std::string, std::map<double, std::set<double>>> at_x;  // case -> x -> values
    for (const auto& m : members) {
      values[m.ref.case_name].insert(parameter(m, name));
      at_x[m.ref.case_name][parameter(m, spec.x)].insert(parameter(m, name));
    }
    for (const auto& [c, v] : values) {
      bool follows_x = true;  // one value at each x: a function of x, not a second parameter
      for (const auto& [x, w] : at_x[c]) follows_x = follows_x && w.size() == 1;
      if (v.size() > 1 && !follows_x) varying[c].insert(name);
    }
  }
  auto line_of = [&](const MemberAnalysis& m) {
    std::string label = m.ref.case_name;
    std::string extra;
    for (const auto& name : varying[m.ref.case_name])
      extra += (extra.empty() ? "" : ", ") + name.substr(name.rfind('.') + 1) + " = " + format_number(parameter(m, name));
    if (!extra.empty()) {
      if (!label.empty()) label += ' ';
      label += '(';
      label += extra;
      label += ')';
    }
    return label;
  };
  for (const auto* m : ordered(members, spec.x)) {
    std::vector<std::string> row{case_label(m->ref.case_name),
                                 m->missing.count(spec.x) ? "n/a: " + m->missing.at(spec.x)
                                                          : format_number(parameter(*m, spec.x)),
                                 m->ref.slug};
    for (const auto& c : spec.columns) {
      const ColumnValue v = column_value(m->fits, c);
      std::string why = v.reason;
      double scale = v.parameter ? normaliser(*m, spec.normalise, why) : k_nan;
      if (!v.parameter || std::isnan(scale)) {
        row.insert(row.end(), {"n/a: " + why, "", ""});
        continue;
      }
      const double value = v.parameter->value / scale;
      const double hw = v.parameter->half_width() / scale;
      row.insert(row.end(), {format_number(value), format_number(hw), format_number(v.fit->r_squared)});
      if (!m->missing.count(spec.x)) {
        auto& s = series[line_of(*m)][c];
        s.x.push_back(parameter(*m, spec.x));
        s.y.push_back(value);
        s.lo.push_back(v.parameter->ci_low / scale);
        s.hi.push_back(v.parameter->ci_high / scale);
      }
    }
    t.rows.push_back(row);
  }
  return t;
}

class TimeTablesSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    outputs.figure_data["tables"] = nlohmann::json::array();
    outputs.fits["tables"] = nlohmann::json::array();
    std::set<std::string> ladder_keys;
    for (const auto& l : context.block.ladders) ladder_keys.insert(l.key);
    if (context.block.bilinear && !context.block.bilinear->ladder.empty()) ladder_keys.insert(context.block.bilinear->ladder);
    for (const auto& spec : context.block.tables) {
      std::map<std::string, std::map<std::string, TableSeries>> series;
      outputs.write_table(time_table(spec, context.members, ladder_keys, series), out_dir / "tables", spec.name);
      outputs.fits["tables"].push_back(
          {{"name", spec.name}, {"x", spec.x}, {"columns", spec.columns}, {"normalise", spec.normalise}});
      nlohmann::json ft{{"name", spec.name}, {"x", spec.x}, {"normalise", spec.normalise}};
      ft["ylabel"] = spec.normalise == "tau_e"     ? "$\\tau/\\tau_e$"
                     : spec.normalise == "tau_v"   ? "$\\tau/\\tau_v$"
                     : spec.normalise == "seconds" ? "$\\tau$ (s)"
                                                   : "$k\\tau$";
      ft["cases"] = nlohmann::json::object();
      for (const auto& [c, cols] : series) {
        nlohmann::json cj{{"columns", nlohmann::json::object()}};
        for (const auto& [col, s] : cols) cj["columns"][col] = {{"x", s.x}, {"y", s.y}, {"lo", s.lo}, {"hi", s.hi}};
        ft["cases"][c] = cj;
      }
      outputs.figure_data["tables"].push_back(ft);
    }
  }
};

}  // namespace

std::unique_ptr<ReportSection> time_tables_section() { return std::make_unique<TimeTablesSection>(); }

}  // namespace capsule::analysis
