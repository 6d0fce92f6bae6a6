// Members against experiments (block "experiments"): per data point of an experiment (a force of
// Mills et al.'s optical tweezers, say) and per measured quantity, the experiment's mean and spread
// beside each member's value where its first phase ended (t_stop: a stretch until steady), one
// column per value of the spec's group (a resolution), the deviation in spreads and the
// difference between the groups. experiments/<data>.md/.csv/.tex, fits.json "experiments",
// figure "experiment_<data>".
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "analysis/report/experiment_data.hpp"
#include "analysis/report/report_section.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

bool same(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(b)); }

// A member's series where its first phase ended: at t_stop when the member has one, else its last value.
double value_at_stop(const MemberAnalysis& m, const std::string& series) {
  const auto it = m.series.find(series);
  if (it == m.series.end() || it->second.size() != m.kt.size() || m.kt.empty()) return k_nan;
  const auto stop = m.markers.find("t_stop");
  if (stop != m.markers.end() && std::isfinite(stop->second)) {
    const double v = interpolate_series(m.kt, it->second, stop->second);
    if (std::isfinite(v)) return v;
  }
  return it->second.back();
}

// The member at (x, group value): a number, or "n/a: why".
struct Cell {
  double value = k_nan;
  std::string why;
};

Cell member_cell(const std::vector<DistinctMember>& members, const ExperimentSpec& spec, double x,
                 std::optional<double> group, const std::string& series) {
  for (const auto& dm : members) {
    const MemberAnalysis& m = *dm.member;
    if (!same(parameter(m, spec.parameter), x)) continue;
    if (group && !same(parameter(m, spec.group), *group)) continue;
    if (m.status != "complete") return {k_nan, incomplete_reason(m)};
    const double v = value_at_stop(m, series);
    if (!std::isfinite(v)) return {k_nan, "member has no series " + series};
    return {v, ""};
  }
  return {k_nan, "no member with " + spec.parameter + " = " + format_number(x) +
                     (group ? ", " + spec.group + " = " + format_number(*group) : "")};
}

std::string cell_text(const Cell& c) { return c.why.empty() ? format_number(c.value) : "n/a: " + c.why; }

// The groups (resolutions) the members hold, ascending; one unnamed group without a spec group.
std::vector<std::optional<double>> groups_of(const ExperimentSpec& spec, const std::vector<DistinctMember>& members) {
  std::vector<std::optional<double>> groups;
  if (!spec.group.empty()) {
    std::set<double> values;
    for (const auto& dm : members)
      if (const double g = parameter(*dm.member, spec.group); std::isfinite(g)) values.insert(g);
    for (double g : values) groups.push_back(g);
  }
  if (groups.empty()) groups.push_back(std::nullopt);
  return groups;
}

// The rows, fits.json points and figure lines of one experiment, and the count within one spread.
struct ExperimentRows {
  ExperimentRows(const ExperimentSpec& s, const std::vector<DistinctMember>& m)
      : spec(s), members(m), groups(groups_of(s, m)) {}
  const ExperimentSpec& spec;
  const std::vector<DistinctMember>& members;
  std::vector<std::optional<double>> groups;
  Table table;
  nlohmann::json points = nlohmann::json::array(), quantities = nlohmann::json::array(),
                 lines = nlohmann::json::array();
  std::map<std::string, std::pair<int, int>> within;  // group name -> (within one spread, compared)

  std::string group_name(const std::optional<double>& g) const {
    return g ? spec.group + " = " + format_number(*g) : std::string("toolkit");
  }

  void header(const std::string& x) {
    table.header = {"quantity", x, "measured", "spread"};
    for (const auto& g : groups) {
      table.header.push_back(g ? "toolkit, " + group_name(g) : "toolkit");
      table.header.push_back(g ? "deviation in spreads, " + group_name(g) : "deviation in spreads");
    }
    if (groups.size() >= 2)
      table.header.push_back("difference " + format_number(*groups.back()) + " - " + format_number(*groups.front()));
  }

  void add_quantity(const ExperimentData& data, const ExperimentQuantity& q) {
    const std::vector<double> xs = data.column(spec.x), mean = data.column(q.measured), spread = data.column(q.spread);
    quantities.push_back({{"measured", q.measured}, {"series", q.series}, {"x", xs}, {"mean", mean}, {"spread", spread}});
    std::vector<nlohmann::json> line_x(groups.size(), nlohmann::json::array()), line_y = line_x;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      std::vector<std::string> row{q.measured, format_number(xs[i]), format_number(mean[i]), format_number(spread[i])};
      nlohmann::json p = {{"quantity", q.measured}, {"series", q.series}, {spec.x, xs[i]}, {"measured", mean[i]},
                          {"spread", spread[i]}, {"toolkit", nlohmann::json::object()},
                          {"deviation_in_spreads", nlohmann::json::object()}};
      std::vector<Cell> cells;
      for (std::size_t k = 0; k < groups.size(); ++k) {
        const Cell c = member_cell(members, spec, xs[i], groups[k], q.series);
        cells.push_back(c);
        const double z = (c.value - mean[i]) / spread[i];
        row.push_back(cell_text(c));
        row.push_back(c.why.empty() ? format_number(z) : "n/a: " + c.why);
        const std::string name = group_name(groups[k]);
        p["toolkit"][name] = c.why.empty() ? json_number(c.value) : nlohmann::json(c.why);
        p["deviation_in_spreads"][name] = json_number(z);
        if (c.why.empty()) {
          auto& w = within[name];
          w.first += std::abs(z) <= 1.0;
          w.second += 1;
          line_x[k].push_back(xs[i]);
          line_y[k].push_back(c.value);
        }
      }
      if (groups.size() >= 2) {
        const Cell& first = cells.front();
        const Cell& last = cells.back();
        row.push_back(first.why.empty() && last.why.empty() ? format_number(last.value - first.value)
                                                            : "n/a: a member missing");
        p["group_difference"] = json_number(last.value - first.value);
      }
      table.rows.push_back(row);
      points.push_back(p);
    }
    for (std::size_t k = 0; k < groups.size(); ++k)
      lines.push_back({{"series", q.series}, {"measured", q.measured}, {"group", group_name(groups[k])},
                       {"x", line_x[k]}, {"y", line_y[k]}});
  }
};

void write_experiment(const ExperimentSpec& spec, const std::vector<DistinctMember>& members, const fs::path& dir,
                      ReportOutputs& outputs) {
  const ExperimentData data = experiment_data(spec.data);
  ExperimentRows r(spec, members);
  r.header(spec.x);
  for (const auto& q : spec.compare) r.add_quantity(data, q);
  const auto& groups = r.groups;
  auto& t = r.table;
  std::string summary;
  nlohmann::json within_json = nlohmann::json::object();
  for (const auto& g : groups) {
    const std::string name = r.group_name(g);
    const auto [in, of] = r.within[name];
    summary += (summary.empty() ? "" : "; ") + name + ": " + std::to_string(in) + " of " + std::to_string(of);
    within_json[name] = {{"within", in}, {"compared", of}};
  }
  t.title = "Members against " + data.source + " (analysis/reference/" + data.name +
            ".csv): each member's value where its first phase ended, the deviation (toolkit - measured) / spread. "
            "Within one spread: " + summary;
  outputs.write_table(t, dir, data.name);
  outputs.fits["experiments"].push_back({{"data", data.name}, {"source", data.source}, {"x", spec.x},
                                         {"parameter", spec.parameter}, {"group", spec.group},
                                         {"within_one_spread", within_json}, {"points", r.points}});
  outputs.figure_data["experiments"].push_back({{"name", data.name}, {"source", data.source}, {"x", spec.x},
                                                {"quantities", r.quantities}, {"lines", r.lines}});
}

class ExperimentSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    if (context.block.experiments.empty()) return;
    const auto members = distinct_members(context.members);
    fs::create_directories(out_dir / "experiments");
    outputs.fits["experiments"] = nlohmann::json::array();
    outputs.figure_data["experiments"] = nlohmann::json::array();
    for (const auto& spec : context.block.experiments) write_experiment(spec, members, out_dir / "experiments", outputs);
  }
};

}  // namespace

std::unique_ptr<ReportSection> experiment_section() { return std::make_unique<ExperimentSection>(); }

}  // namespace capsule::analysis
