// Accuracy against cost (block "accuracy"): members grouped by physical case (the scene
// without the setting keys); per member the relative error of each quantity against a
// reference (given, or a ladder's extrapolation) and its cost in core-seconds
// (wall_seconds x threads); the non-dominated settings and the cheapest within each bound.
// accuracy/<case>.*, accuracy/reference.*, accuracy/pareto.*, accuracy/cheapest.*.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "analysis/report/member_quantity.hpp"
#include "analysis/fit/pareto.hpp"
#include "analysis/report/report_section.hpp"
#include "analysis/report/resolution_ladder.hpp"
#include "analysis/report/scene_parameter.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

std::string pointer_of(const std::string& dotted) {
  std::string p = "/" + dotted;
  std::replace(p.begin(), p.end(), '.', '/');
  return p;
}

nlohmann::json physical_scene(const nlohmann::json& scene, const std::vector<std::string>& settings) {
  nlohmann::json out = scene;
  for (const auto& key : settings) out = scene_without(out, pointer_of(key));
  return out;
}

std::string percent(double relative) { return format_number(100.0 * relative); }

struct Reference {
  bool found = false;
  double value = 0.0;
  std::string source;  // where it came from, or why there is none
};

struct CaseGroup {
  nlohmann::json physical;
  std::vector<std::string> cases;
  std::vector<const MemberAnalysis*> members;
  std::string label, stem;
};

bool holds_case(const CaseGroup& g, const std::string& case_name) {
  return std::find(g.cases.begin(), g.cases.end(), case_name) != g.cases.end();
}

// The members grouped by physical case, each group labelled (its cases, and the scene leaves
// that tell it from the others) and given its file stem.
std::vector<CaseGroup> physical_cases(const ReportContext& context, const AccuracySpec& spec) {
  std::vector<CaseGroup> groups;
  std::map<std::string, std::size_t> index;
  for (const auto& d : distinct_members(context.members)) {
    nlohmann::json phys = physical_scene(d.member->scene, spec.settings);
    const auto [it, fresh] = index.emplace(phys.dump(), groups.size());
    if (fresh) groups.push_back({phys, {}, {}, "", ""});
    CaseGroup& g = groups[it->second];
    for (const auto& c : d.cases)
      if (!holds_case(g, c)) g.cases.push_back(c);
    g.members.push_back(d.member);
  }
  std::vector<nlohmann::json> physicals;
  for (const auto& g : groups) physicals.push_back(g.physical);
  std::map<std::string, int> stems;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    CaseGroup& g = groups[gi];
    g.label = cases_label(g.cases);
    if (const std::string extra = differing_leaves(physicals, gi); !extra.empty() && groups.size() > 1)
      g.label += " (" + extra + ")";
    std::string stem = "case_" + file_slug(g.cases.empty() || g.cases.front().empty() ? "all" : g.cases.front());
    if (const int n = ++stems[stem]; n > 1) stem += "_" + std::to_string(n);
    g.stem = stem;
  }
  return groups;
}

// Where each quantity's reference comes from: the block's values and the ladders it names
// (each ladder computed once).
class References {
 public:
  References(const ReportContext& context, const AccuracySpec& spec, const std::vector<CaseGroup>& groups)
      : spec_(spec), groups_(groups) {
    for (const auto& ref : spec.reference)
      if (!ref.ladder.empty() && !ladders_.count(ref.ladder))
        for (const auto& l : context.block.ladders)
          if (l.name == ref.ladder) ladders_.emplace(l.name, ladder_report(context, l));
  }

  // The first reference that applies to the case and gives the quantity, or why none does.
  Reference of(const CaseGroup& g, const std::string& quantity) const {
    Reference r;
    r.source = "no reference for this case in /analysis/accuracy/reference";
    for (const auto& ref : spec_.reference) {
      if (!ref.case_name.empty() && !holds_case(g, ref.case_name)) continue;
      if (const auto it = ref.values.find(quantity); it != ref.values.end()) return given(ref, it->second);
      if (!ref.ladder.empty() && extrapolated(ref, g, quantity, r)) return r;
    }
    return r;
  }

 private:
  // A value given in the block; ambiguous when its case holds several physical cases.
  Reference given(const ReferenceSpec& ref, double value) const {
    Reference r;
    const auto holders = std::count_if(groups_.begin(), groups_.end(), [&](const CaseGroup& o) { return holds_case(o, ref.case_name); });
    if (!ref.case_name.empty() && holders > 1) {
      r.source = "reference for case " + ref.case_name + " is ambiguous: the case holds " + std::to_string(holders) +
                 " physical cases";
      return r;
    }
    r.found = true;
    r.value = value;
    r.source = "given in the block";
    return r;
  }

  // The ladder's extrapolation of the case's quantity from its group with the most levels;
  // false, with r.source saying why, when the ladder has none.
  bool extrapolated(const ReferenceSpec& ref, const CaseGroup& g, const std::string& quantity, Reference& r) const {
    const LadderRow* best = nullptr;
    std::string why = "ladder " + ref.ladder + " has no group of this physical case";
    for (const auto& row : ladders_.at(ref.ladder).rows) {
      if (row.quantity != quantity || physical_scene(row.rest_scene, spec_.settings) != g.physical) continue;
      if (!row.refusal.empty()) {
        why = "ladder " + ref.ladder + ": " + row.refusal;
        continue;
      }
      if (!best || row.result.levels > best->result.levels) best = &row;
    }
    if (!best) {
      r.source = why;
      return false;
    }
    r.found = true;
    r.value = best->result.extrapolated;
    r.source = "ladder " + ref.ladder + ": extrapolated from levels " + best->used_levels + " (p = " +
               format_number(best->result.order) + (best->result.order_observed ? ", observed)" : ", assumed)");
    return true;
  }

  const AccuracySpec& spec_;
  const std::vector<CaseGroup>& groups_;
  std::map<std::string, LadderReport> ladders_;
};

// A member's setting: the values of the setting keys that vary within its case.
class Settings {
 public:
  Settings(const AccuracySpec& spec, const CaseGroup& g) {
    for (const auto& key : spec.settings) {
      std::set<std::string> values;
      for (const auto* m : g.members) {
        const nlohmann::json* v = scene_value_at(m->scene, key);
        values.insert(v ? v->dump() : "(absent)");
      }
      if (values.size() > 1) varying.push_back(key);
    }
  }
  std::string of(const MemberAnalysis& m) const {
    std::string s;
    for (const auto& key : varying) {
      const nlohmann::json* v = scene_value_at(m.scene, key);
      s += (s.empty() ? "" : ", ") + key.substr(key.rfind('.') + 1) + " = " + (v ? value_text(*v) : "(absent)");
    }
    return s.empty() ? std::string("(base)") : s;
  }
  std::vector<std::string> varying;
};

// The tables over all cases: the references, the non-dominated settings, the cheapest within each bound.
struct SummaryTables {
  Table references, pareto, cheapest;
  SummaryTables() {
    references.title = "Accuracy references: the value each member's error is measured against";
    references.header = {"case", "quantity", "reference", "source"};
    pareto.title = "Non-dominated settings (no other setting is both cheaper and more accurate), by cost";
    pareto.header = {"case", "quantity", "setting", "member", "cost (core-s)", "error %"};
    cheapest.title = "Cheapest setting within each relative-error bound";
    cheapest.header = {"case", "quantity", "bound %", "setting", "member", "cost (core-s)", "error %"};
  }
};

// One case's members sorted by setting, with each quantity's (cost, error) per member.
struct CaseMembers {
  std::vector<const MemberAnalysis*> members;
  std::map<std::string, std::vector<CostError>> points;  // quantity -> one per member
};

// The relative error of a quantity against its reference, or NaN with why.
double relative_error(const QuantityValue& v, const Reference& r, std::string& why) {
  if (!v.found) why = v.reason;
  else if (!r.found) why = "no reference: " + r.source;
  else if (r.value == 0.0) why = "reference 0: relative error undefined";
  else return std::abs(v.value - r.value) / std::abs(r.value);
  return k_nan;
}

// The case's table of error and cost per member (accuracy/<case>.*) and its members in fits.json.
CaseMembers member_errors(const AccuracySpec& spec, const CaseGroup& g, const Settings& settings,
                          std::map<std::string, Reference>& refs, Table& t, nlohmann::json& cj) {
  t.title = g.label + ": error against the reference and cost (core-seconds = wall seconds x threads)";
  t.header = {"setting", "member", "status", "wall s", "threads", "cost (core-s)"};
  for (const auto& q : spec.quantities) {
    t.header.push_back(q);
    t.header.push_back(q + " error %");
  }
  CaseMembers out{g.members, {}};
  std::stable_sort(out.members.begin(), out.members.end(),
                   [&](const MemberAnalysis* a, const MemberAnalysis* b) { return settings.of(*a) < settings.of(*b); });
  for (const auto* m : out.members) {
    const bool has_cost = std::isfinite(m->wall_seconds) && m->wall_seconds >= 0.0 && m->threads > 0;
    const double cost = has_cost ? m->wall_seconds * static_cast<double>(m->threads) : k_nan;
    std::vector<std::string> row{settings.of(*m), m->ref.slug, m->status,
                                 std::isfinite(m->wall_seconds) ? format_number(m->wall_seconds) : "n/a",
                                 m->threads > 0 ? std::to_string(m->threads) : "n/a",
                                 has_cost ? format_number(cost) : "n/a: no wall_seconds or threads in the member file"};
    nlohmann::json mj{{"member", m->ref.slug}, {"setting", settings.of(*m)}, {"status", m->status},
                      {"cost_core_seconds", json_number(cost)}, {"errors", nlohmann::json::object()}};
    for (const auto& q : spec.quantities) {
      const QuantityValue v = member_quantity(*m, q);
      std::string why;
      const double err = relative_error(v, refs[q], why);
      row.push_back(v.found ? format_number(v.value) : "n/a: " + v.reason);
      row.push_back(std::isfinite(err) ? percent(err) : "n/a: " + why);
      mj["errors"][q] = std::isfinite(err) ? nlohmann::json(err) : nlohmann::json(why);
      out.points[q].push_back({has_cost ? cost : k_nan, err});
    }
    t.rows.push_back(row);
    cj["members"].push_back(mj);
  }
  return out;
}

// The figure of error against cost, log-log; an error of 0 (the reference member itself)
// cannot be drawn.
nlohmann::json cost_error_figure(const CaseGroup& g, const std::string& q, const CaseMembers& cm, const Settings& settings,
                                 const std::vector<std::size_t>& front) {
  const auto& p = cm.points.at(q);
  nlohmann::json fig{{"name", "accuracy_" + file_slug(g.stem) + "_" + file_slug(q)},
                     {"title", g.label + ": " + q},
                     {"points", {{"cost", nlohmann::json::array()}, {"error", nlohmann::json::array()},
                                 {"label", nlohmann::json::array()}}},
                     {"front", {{"cost", nlohmann::json::array()}, {"error", nlohmann::json::array()}}}};
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::isfinite(p[i].cost) && std::isfinite(p[i].error) && p[i].cost > 0 && p[i].error > 0) {
      fig["points"]["cost"].push_back(p[i].cost);
      fig["points"]["error"].push_back(p[i].error);
      fig["points"]["label"].push_back(settings.of(*cm.members[i]));
    }
  for (const std::size_t i : front)
    if (p[i].cost > 0 && p[i].error > 0) {
      fig["front"]["cost"].push_back(p[i].cost);
      fig["front"]["error"].push_back(p[i].error);
    }
  return fig;
}

// A quantity's non-dominated settings and the cheapest within each bound (the summary tables'
// rows, fits.json's "pareto"), and its figure.
void pareto_and_cheapest(const AccuracySpec& spec, const CaseGroup& g, const std::string& q, const CaseMembers& cm,
                         const Settings& settings, SummaryTables& tables, nlohmann::json& cj, ReportOutputs& outputs) {
  const auto& p = cm.points.at(q);
  const auto& members = cm.members;
  const auto front = pareto_front(p);
  if (front.empty()) tables.pareto.rows.push_back({g.label, q, "n/a: no member with both a cost and an error", "", "", ""});
  nlohmann::json fj = nlohmann::json::array();
  for (const std::size_t i : front) {
    tables.pareto.rows.push_back({g.label, q, settings.of(*members[i]), members[i]->ref.slug, format_number(p[i].cost), percent(p[i].error)});
    fj.push_back(members[i]->ref.slug);
  }
  cj["pareto"][q] = fj;
  for (const double bound : spec.bounds) {
    const auto best = cheapest_within(p, bound);
    if (best)
      tables.cheapest.rows.push_back({g.label, q, percent(bound), settings.of(*members[*best]), members[*best]->ref.slug,
                                      format_number(p[*best].cost), percent(p[*best].error)});
    else
      tables.cheapest.rows.push_back({g.label, q, percent(bound), "n/a: none within " + percent(bound) + " %", "", "", ""});
  }
  nlohmann::json fig = cost_error_figure(g, q, cm, settings, front);
  if (!fig["points"]["cost"].empty()) outputs.figure_data["accuracy"].push_back(fig);
}

// One physical case: its references, its table of members, its pareto front and cheapest settings.
nlohmann::json write_case(const AccuracySpec& spec, const CaseGroup& g, const References& references, const fs::path& dir,
                          SummaryTables& tables, ReportOutputs& outputs) {
  const Settings settings(spec, g);
  std::map<std::string, Reference> refs;
  for (const auto& q : spec.quantities) {
    refs[q] = references.of(g, q);
    tables.references.rows.push_back({g.label, q, refs[q].found ? format_number(refs[q].value) : "n/a", refs[q].source});
  }
  Table t;
  nlohmann::json cj{{"case", g.label}, {"cases", g.cases}, {"file", "accuracy/" + g.stem}, {"setting_keys", settings.varying},
                    {"members", nlohmann::json::array()}};
  const CaseMembers cm = member_errors(spec, g, settings, refs, t, cj);
  outputs.write_table(t, dir, g.stem);
  cj["pareto"] = nlohmann::json::object();
  for (const auto& q : spec.quantities) pareto_and_cheapest(spec, g, q, cm, settings, tables, cj, outputs);
  return cj;
}

class AccuracySection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    if (!context.block.accuracy) return;
    const AccuracySpec& spec = *context.block.accuracy;
    const fs::path dir = out_dir / "accuracy";
    const std::vector<CaseGroup> groups = physical_cases(context, spec);
    const References references(context, spec, groups);
    SummaryTables tables;
    nlohmann::json aj{{"settings", spec.settings}, {"quantities", spec.quantities}, {"bounds", spec.bounds},
                      {"cases", nlohmann::json::array()}};
    outputs.figure_data["accuracy"] = nlohmann::json::array();
    for (const CaseGroup& g : groups) aj["cases"].push_back(write_case(spec, g, references, dir, tables, outputs));
    if (groups.empty()) tables.references.rows.push_back({"(none)", "", "n/a", "no members"});
    outputs.write_table(tables.references, dir, "reference");
    outputs.write_table(tables.pareto, dir, "pareto");
    outputs.write_table(tables.cheapest, dir, "cheapest");
    outputs.fits["accuracy"] = aj;
  }
};

}  // namespace

std::unique_ptr<ReportSection> accuracy_section() { return std::make_unique<AccuracySection>(); }

}  // namespace capsule::analysis
