#include "analysis/report/resolution_ladder.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/report/member_quantity.hpp"
#include "analysis/report/scene_parameter.hpp"
#include "analysis/report/table.hpp"

namespace capsule::analysis {

double ladder_spacing(const std::string& spacing, double x) {
  double h = k_nan;
  if (spacing == "1/x") h = 1.0 / x;
  else if (spacing == "2^-x") h = std::exp2(-x);
  else if (spacing == "x") h = x;
  return std::isfinite(h) && h > 0.0 ? h : k_nan;
}

namespace {

// The members that differ only in the ladder's key, with the cases they belong to.
struct LadderGroup {
  nlohmann::json rest;
  std::vector<std::string> cases;
  std::vector<std::pair<double, const MemberAnalysis*>> members;  // (x, member)
};

// Groups the members of the ladder's cases by their scene without the key; a member without a
// usable number there goes to report.unplaced.
std::vector<LadderGroup> group_members(const ReportContext& context, const LadderSpec& spec, LadderReport& report) {
  std::string pointer = "/" + spec.key;
  std::replace(pointer.begin(), pointer.end(), '.', '/');
  std::vector<LadderGroup> groups;
  std::map<std::string, std::size_t> index;  // rest scene text -> group
  for (const auto& d : distinct_members(context.members)) {
    const MemberAnalysis& m = *d.member;
    if (!spec.cases.empty() && std::none_of(d.cases.begin(), d.cases.end(), [&](const std::string& c) {
          return std::find(spec.cases.begin(), spec.cases.end(), c) != spec.cases.end();
        }))
      continue;
    const nlohmann::json* v = scene_value_at(m.scene, spec.key);
    if (!v || !v->is_number()) {
      report.unplaced.push_back(m.ref.slug + ": scene has no number at " + spec.key);
      continue;
    }
    const double x = v->get<double>();
    if (std::isnan(ladder_spacing(spec.spacing, x))) {
      report.unplaced.push_back(m.ref.slug + ": " + spec.key + " = " + format_number(x) + " gives no h > 0 by " +
                                spec.spacing);
      continue;
    }
    nlohmann::json rest = scene_without(m.scene, pointer);
    const auto [it, fresh] = index.emplace(rest.dump(), groups.size());
    if (fresh) groups.push_back({rest, {}, {}});
    LadderGroup& g = groups[it->second];
    for (const auto& c : d.cases)
      if (std::find(g.cases.begin(), g.cases.end(), c) == g.cases.end()) g.cases.push_back(c);
    g.members.emplace_back(x, &m);
  }
  return groups;
}

// One quantity over one group's levels (finest first): the Richardson extrapolation of the
// finest usable levels, or why there is none.
LadderRow ladder_row(const LadderGroup& g, const std::string& label, const std::string& quantity,
                     const LadderSpec& spec) {
  const std::string short_key = spec.key.substr(spec.key.rfind('.') + 1);
  LadderRow row;
  row.group = label;
  row.cases = g.cases;
  row.rest_scene = g.rest;
  row.quantity = quantity;
  std::vector<LadderLevel> usable;
  for (const auto& [x, m] : g.members) {
    LadderLevelValue lv;
    lv.x = x;
    lv.member = m;
    const QuantityValue q = member_quantity(*m, quantity);
    lv.has_value = q.found && std::isfinite(q.value);
    lv.value = q.value;
    lv.reason = q.found ? "not finite" : q.reason;
    row.levels.push_back(lv);
    if (lv.has_value) {
      usable.push_back({ladder_spacing(spec.spacing, x), q.value});
      if (usable.size() <= 3) row.used_levels += (row.used_levels.empty() ? "" : ", ") + format_number(x);
    } else {
      row.excluded.push_back(short_key + " = " + format_number(x) + " (" + m->ref.slug + "): " + lv.reason);
    }
  }
  if (!row.levels.front().has_value) {
    row.refusal = "finest level " + short_key + " = " + format_number(row.levels.front().x) +
                  " has no value: " + row.levels.front().reason;
  } else {
    row.result = richardson(usable, spec.assumed_order);
    if (!row.result.ok) row.refusal = row.result.reason;
    if (row.levels.size() == 1)
      row.refusal = "one level only (" + short_key + " = " + format_number(row.levels.front().x) + "): no ladder";
  }
  return row;
}

}  // namespace

LadderReport ladder_report(const ReportContext& context, const LadderSpec& spec) {
  LadderReport report;
  std::vector<LadderGroup> groups = group_members(context, spec, report);
  std::vector<nlohmann::json> rests;
  for (const auto& g : groups) rests.push_back(g.rest);
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    LadderGroup& g = groups[gi];
    std::stable_sort(g.members.begin(), g.members.end(), [&](const auto& a, const auto& b) {
      return ladder_spacing(spec.spacing, a.first) < ladder_spacing(spec.spacing, b.first);
    });
    std::string label = cases_label(g.cases);
    if (const std::string extra = differing_leaves(rests, gi); !extra.empty()) label += " (" + extra + ")";
    for (const auto& quantity : spec.quantities) report.rows.push_back(ladder_row(g, label, quantity, spec));
  }
  return report;
}

}  // namespace capsule::analysis
