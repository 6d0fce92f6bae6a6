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

class AccuracySection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    if (!context.block.accuracy) return;
    const AccuracySpec& spec = *context.block.accuracy;
    const fs::path dir = out_dir / "accuracy";

    // Physical cases.
    std::vector<CaseGroup> groups;
    std::map<std::string, std::size_t> index;
    for (const auto& d : distinct_members(context.members)) {
      nlohmann::json phys = physical_scene(d.member->scene, spec.settings);
      const auto [it, fresh] = index.emplace(phys.dump(), groups.size());
      if (fresh) groups.push_back({phys, {}, {}, "", ""});
      CaseGroup& g = groups[it->second];
      for (const auto& c : d.cases)
        if (std::find(g.cases.begin(), g.cases.end(), c) == g.cases.end()) g.cases.push_back(c);
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

    // Ladders a reference names, computed once.
    std::map<std::string, LadderReport> ladders;
    for (const auto& ref : spec.reference)
      if (!ref.ladder.empty() && !ladders.count(ref.ladder))
        for (const auto& l : context.block.ladders)
          if (l.name == ref.ladder) ladders.emplace(l.name, ladder_report(context, l));

    auto reference_of = [&](const CaseGroup& g, const std::string& quantity) {
      Reference r;
      r.source = "no reference for this case in /analysis/accuracy/reference";
      for (const auto& ref : spec.reference) {
        const bool applies = ref.case_name.empty() ||
                             std::find(g.cases.begin(), g.cases.end(), ref.case_name) != g.cases.end();
        if (!applies) continue;
        if (const auto it = ref.values.find(quantity); it != ref.values.end()) {
          const auto holders = std::count_if(groups.begin(), groups.end(), [&](const CaseGroup& o) {
            return std::find(o.cases.begin(), o.cases.end(), ref.case_name) != o.cases.end();
          });
          if (!ref.case_name.empty() && holders > 1) {
            r.source = "reference for case " + ref.case_name + " is ambiguous: the case holds " +
                       std::to_string(holders) + " physical cases";
            return r;
          }
          r.found = true;
          r.value = it->second;
          r.source = "given in the block";
          return r;
        }
        if (!ref.ladder.empty()) {
          const LadderRow* best = nullptr;
          std::string why = "ladder " + ref.ladder + " has no group of this physical case";
          for (const auto& row : ladders.at(ref.ladder).rows) {
            if (row.quantity != quantity || physical_scene(row.rest_scene, spec.settings) != g.physical) continue;
            if (!row.refusal.empty()) {
              why = "ladder " + ref.ladder + ": " + row.refusal;
              continue;
            }
            if (!best || row.result.levels > best->result.levels) best = &row;
          }
          if (!best) {
            r.source = why;
            continue;
          }
          r.found = true;
          r.value = best->result.extrapolated;
          r.source = "ladder " + ref.ladder + ": extrapolated from levels " + best->used_levels + " (p = " +
                     format_number(best->result.order) + (best->result.order_observed ? ", observed)" : ", assumed)");
          return r;
        }
      }
      return r;
    };

    Table ref_table;
    ref_table.title = "Accuracy references: the value each member's error is measured against";
    ref_table.header = {"case", "quantity", "reference", "source"};
    Table pareto_table;
    pareto_table.title = "Non-dominated settings (no other setting is both cheaper and more accurate), by cost";
    pareto_table.header = {"case", "quantity", "setting", "member", "cost (core-s)", "error %"};
    Table cheap_table;
    cheap_table.title = "Cheapest setting within each relative-error bound";
    cheap_table.header = {"case", "quantity", "bound %", "setting", "member", "cost (core-s)", "error %"};
    nlohmann::json aj{{"settings", spec.settings}, {"quantities", spec.quantities}, {"bounds", spec.bounds},
                      {"cases", nlohmann::json::array()}};
    outputs.figure_data["accuracy"] = nlohmann::json::array();

    for (const CaseGroup& g : groups) {
      // The setting: the setting keys whose values vary within this case.
      std::vector<std::string> varying;
      for (const auto& key : spec.settings) {
        std::set<std::string> values;
        for (const auto* m : g.members) {
          const nlohmann::json* v = scene_value_at(m->scene, key);
          values.insert(v ? v->dump() : "(absent)");
        }
        if (values.size() > 1) varying.push_back(key);
      }
      auto setting_of = [&](const MemberAnalysis& m) {
        std::string s;
        for (const auto& key : varying) {
          const nlohmann::json* v = scene_value_at(m.scene, key);
          s += (s.empty() ? "" : ", ") + key.substr(key.rfind('.') + 1) + " = " + (v ? value_text(*v) : "(absent)");
        }
        return s.empty() ? std::string("(base)") : s;
      };

      std::map<std::string, Reference> refs;
      for (const auto& q : spec.quantities) {
        refs[q] = reference_of(g, q);
        ref_table.rows.push_back({g.label, q, refs[q].found ? format_number(refs[q].value) : "n/a", refs[q].source});
      }

      Table t;
      t.title = g.label + ": error against the reference and cost (core-seconds = wall seconds x threads)";
      t.header = {"setting", "member", "status", "wall s", "threads", "cost (core-s)"};
      for (const auto& q : spec.quantities) {
        t.header.push_back(q);
        t.header.push_back(q + " error %");
      }
      std::map<std::string, std::vector<CostError>> points;  // quantity -> one per member
      nlohmann::json cj{{"case", g.label}, {"cases", g.cases}, {"file", "accuracy/" + g.stem}, {"setting_keys", varying},
                        {"members", nlohmann::json::array()}};
      std::vector<const MemberAnalysis*> members = g.members;
      std::stable_sort(members.begin(), members.end(), [&](const MemberAnalysis* a, const MemberAnalysis* b) {
        return setting_of(*a) < setting_of(*b);
      });
      for (const auto* m : members) {
        const bool has_cost = std::isfinite(m->wall_seconds) && m->wall_seconds >= 0.0 && m->threads > 0;
        const double cost = has_cost ? m->wall_seconds * static_cast<double>(m->threads) : k_nan;
        std::vector<std::string> row{setting_of(*m), m->ref.slug, m->status,
                                     std::isfinite(m->wall_seconds) ? format_number(m->wall_seconds) : "n/a",
                                     m->threads > 0 ? std::to_string(m->threads) : "n/a",
                                     has_cost ? format_number(cost) : "n/a: no wall_seconds or threads in the member file"};
        nlohmann::json mj{{"member", m->ref.slug}, {"setting", setting_of(*m)}, {"status", m->status},
                          {"cost_core_seconds", json_number(cost)}, {"errors", nlohmann::json::object()}};
        for (const auto& q : spec.quantities) {
          const QuantityValue v = member_quantity(*m, q);
          const Reference& r = refs[q];
          double err = k_nan;
          std::string why;
          if (!v.found) why = v.reason;
          else if (!r.found) why = "no reference: " + r.source;
          else if (r.value == 0.0) why = "reference 0: relative error undefined";
          else err = std::abs(v.value - r.value) / std::abs(r.value);
          row.push_back(v.found ? format_number(v.value) : "n/a: " + v.reason);
          row.push_back(std::isfinite(err) ? percent(err) : "n/a: " + why);
          mj["errors"][q] = std::isfinite(err) ? nlohmann::json(err) : nlohmann::json(why);
          points[q].push_back({has_cost ? cost : k_nan, err});
        }
        t.rows.push_back(row);
        cj["members"].push_back(mj);
      }
      outputs.write_table(t, dir, g.stem);

      cj["pareto"] = nlohmann::json::object();
      for (const auto& q : spec.quantities) {
        const auto& p = points[q];
        const auto front = pareto_front(p);
        if (front.empty())
          pareto_table.rows.push_back({g.label, q, "n/a: no member with both a cost and an error", "", "", ""});
        nlohmann::json fj = nlohmann::json::array();
        for (const std::size_t i : front) {
          pareto_table.rows.push_back(
              {g.label, q, setting_of(*members[i]), members[i]->ref.slug, format_number(p[i].cost), percent(p[i].error)});
          fj.push_back(members[i]->ref.slug);
        }
        cj["pareto"][q] = fj;
        for (const double bound : spec.bounds) {
          const auto best = cheapest_within(p, bound);
          if (best)
            cheap_table.rows.push_back({g.label, q, percent(bound), setting_of(*members[*best]),
                                        members[*best]->ref.slug, format_number(p[*best].cost),
                                        percent(p[*best].error)});
          else
            cheap_table.rows.push_back({g.label, q, percent(bound), "n/a: none within " + percent(bound) + " %", "", "",
                                        ""});
        }
        // Figure: error against cost, log-log; an error of 0 (the reference member itself) cannot be drawn.
        nlohmann::json fig{{"name", "accuracy_" + file_slug(g.stem) + "_" + file_slug(q)},
                           {"title", g.label + ": " + q},
                           {"points", {{"cost", nlohmann::json::array()}, {"error", nlohmann::json::array()},
                                       {"label", nlohmann::json::array()}}},
                           {"front", {{"cost", nlohmann::json::array()}, {"error", nlohmann::json::array()}}}};
        for (std::size_t i = 0; i < p.size(); ++i)
          if (std::isfinite(p[i].cost) && std::isfinite(p[i].error) && p[i].cost > 0 && p[i].error > 0) {
            fig["points"]["cost"].push_back(p[i].cost);
            fig["points"]["error"].push_back(p[i].error);
            fig["points"]["label"].push_back(setting_of(*members[i]));
          }
        for (const std::size_t i : front)
          if (p[i].cost > 0 && p[i].error > 0) {
            fig["front"]["cost"].push_back(p[i].cost);
            fig["front"]["error"].push_back(p[i].error);
          }
        if (!fig["points"]["cost"].empty()) outputs.figure_data["accuracy"].push_back(fig);
      }
      aj["cases"].push_back(cj);
    }
    if (groups.empty()) ref_table.rows.push_back({"(none)", "", "n/a", "no members"});
    outputs.write_table(ref_table, dir, "reference");
    outputs.write_table(pareto_table, dir, "pareto");
    outputs.write_table(cheap_table, dir, "cheapest");
    outputs.fits["accuracy"] = aj;
  }
};

}  // namespace

std::unique_ptr<ReportSection> accuracy_section() { return std::make_unique<AccuracySection>(); }

}  // namespace capsule::analysis
