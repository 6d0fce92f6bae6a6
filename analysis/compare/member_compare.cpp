#include "analysis/compare/member_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/fit/member_fits.hpp"

namespace capsule::analysis {

namespace {

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

// The fitted times, in the order of analysis/README.md "What each fit fits".
constexpr const char* k_times[] = {"response.k_tau_s",   "recovery.k_tau_r",
                                   "two_phase.k_tau_R1", "two_phase.k_tau_R2",
                                   "double_exponential.k_tau_R1", "double_exponential.k_tau_R2",
                                   "double_exponential_free.k_tau_R1", "double_exponential_free.k_tau_R2"};

// The key of MemberFits that holds a time ("two_phase.k_tau_R2" -> "two_phase_R2").
std::string fit_key(const std::string& time) {
  const auto dot = time.find('.');
  const std::string fit = time.substr(0, dot);
  if (fit == "two_phase") return time.substr(dot + 1) == "k_tau_R1" ? "two_phase_R1" : "two_phase_R2";
  return fit;
}

struct Member {
  std::string case_name, slug;
  std::map<std::string, double> parameters;  // null in fits.json -> NaN
  MemberFits fits;
  std::string tiebreak;  // the slug, when the key alone does not identify the member
};

double value_of(const Member& m, const std::string& name) {
  const auto it = m.parameters.find(name);
  return it == m.parameters.end() ? k_nan : it->second;
}

// Parameters are read back from JSON, but two campaigns may spell a value differently (0.1 vs 1e-1 * 1).
bool same_value(double x, double y) {
  if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
  return std::abs(x - y) <= 1e-9 * std::max({1.0, std::abs(x), std::abs(y)});
}

std::vector<Member> read_members(const CampaignFits& c) {
  std::vector<Member> out;
  const auto members = c.fits.value("members", nlohmann::json::array());
  for (std::size_t i = 0; i < members.size(); ++i) {
    const auto& j = members[i];
    try {
      Member m;
      m.case_name = j.value("case", "");
      m.slug = j.value("slug", j.value("id", ""));
      if (j.contains("parameters") && j["parameters"].is_object())
        for (const auto& [k, v] : j["parameters"].items()) m.parameters[k] = v.is_number() ? v.get<double>() : k_nan;
      if (j.contains("fits") && j["fits"].is_object())
        for (const auto& [k, v] : j["fits"].items()) m.fits[k] = fit_result_from_json(v);
      out.push_back(std::move(m));
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(c.name + ": fits.json: /members/" + std::to_string(i) + ": " + e.what());
    }
  }
  return out;
}

// Table x parameters and parameters that vary among the members of one case.
std::set<std::string> identifying(const CampaignFits& c, const std::vector<Member>& members) {
  std::set<std::string> names;
  for (const auto& t : c.fits.value("tables", nlohmann::json::array()))
    if (t.is_object() && t.contains("x") && t["x"].is_string()) names.insert(t["x"].get<std::string>());
  std::map<std::string, std::vector<const Member*>> by_case;
  for (const auto& m : members) by_case[m.case_name].push_back(&m);
  for (const auto& [case_name, group] : by_case) {
    std::set<std::string> all;
    for (const auto* m : group)
      for (const auto& [k, v] : m->parameters) all.insert(k);
    for (const auto& name : all)
      for (const auto* m : group)
        if (!same_value(value_of(*m, name), value_of(*group.front(), name))) {
          names.insert(name);
          break;
        }
  }
  return names;
}

bool same_key(const Member& a, const Member& b, const std::vector<std::string>& names) {
  if (a.case_name != b.case_name || a.tiebreak != b.tiebreak) return false;
  for (const auto& n : names)
    if (!same_value(value_of(a, n), value_of(b, n))) return false;
  return true;
}

std::string pm(double v, double hw) { return format_number(v) + " ± " + format_number(hw); }

std::string case_label(const std::string& c) { return c.empty() ? "(all)" : c; }

struct Group {
  const Member* first = nullptr;          // the key's owner (first campaign holding the member)
  std::vector<const Member*> in;          // per campaign, nullptr when absent
  std::size_t case_rank = 0;
};

// Members that share a key within their campaign (e.g. repeated runs) are told apart by slug,
// and so is every member with that key in every campaign, so that the slugs match across them.
void break_ties(std::vector<std::vector<Member>>& members, const std::vector<std::string>& key_names) {
  std::vector<const Member*> shared;
  for (const auto& campaign : members)
    for (std::size_t i = 0; i < campaign.size(); ++i)
      for (std::size_t k = i + 1; k < campaign.size(); ++k)
        if (same_key(campaign[i], campaign[k], key_names)) shared.push_back(&campaign[i]);
  std::vector<Member*> tie;
  for (auto& campaign : members)
    for (auto& m : campaign)
      if (std::any_of(shared.begin(), shared.end(), [&](const Member* s) { return same_key(*s, m, key_names); }))
        tie.push_back(&m);
  for (auto* m : tie) m->tiebreak = m->slug;
}

// The members matched across the campaigns, by case (first appearance), then by the key
// parameters (NaN last), then by slug.
std::vector<Group> match_members(const std::vector<std::vector<Member>>& members, const std::vector<std::string>& key_names) {
  std::map<std::string, std::size_t> case_rank;
  std::vector<Group> groups;
  for (std::size_t c = 0; c < members.size(); ++c)
    for (const auto& m : members[c]) {
      case_rank.emplace(m.case_name, case_rank.size());
      auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
        return !g.in[c] && same_key(*g.first, m, key_names);
      });
      if (it == groups.end()) {
        groups.push_back({&m, std::vector<const Member*>(members.size(), nullptr), case_rank[m.case_name]});
        it = groups.end() - 1;
      }
      it->in[c] = &m;
    }
  std::stable_sort(groups.begin(), groups.end(), [&](const Group& p, const Group& q) {
    if (p.case_rank != q.case_rank) return p.case_rank < q.case_rank;
    for (const auto& n : key_names) {
      const double x = value_of(*p.first, n), y = value_of(*q.first, n);
      if (same_value(x, y)) continue;
      if (std::isnan(x) != std::isnan(y)) return std::isnan(y);
      return x < y;
    }
    return p.first->tiebreak < q.first->tiebreak;
  });
  return groups;
}

// A matched member as the tables name it: its key parameters, and its slug where they do not tell it.
std::string group_label(const Group& g, const std::vector<std::string>& key_names) {
  std::string s;
  for (const auto& n : key_names) {
    const double v = value_of(*g.first, n);
    s += (s.empty() ? "" : ", ") + n + " = " + (std::isnan(v) ? std::string("n/a") : format_number(v));
  }
  if (!g.first->tiebreak.empty() || s.empty()) s += (s.empty() ? "" : " ") + ("[" + g.first->slug + "]");
  return s;
}

// A later campaign's time against the first's: the difference and whether the 95 % intervals
// overlap (counted in the result).
void against_first(const FitParameter* a, const FitParameter* b, std::vector<std::string>& row, MemberComparison& result) {
  if (!a || !b) {
    row.insert(row.end(), {"", ""});
    return;
  }
  row.push_back(format_number(b->value - a->value));
  if (!std::isfinite(a->ci_low) || !std::isfinite(a->ci_high) || !std::isfinite(b->ci_low) || !std::isfinite(b->ci_high)) {
    row.push_back("n/a: no 95 % interval");
    return;
  }
  const bool overlap = a->ci_low <= b->ci_high && b->ci_low <= a->ci_high;
  ++result.compared;
  if (!overlap) ++result.non_overlapping;
  row.push_back(overlap ? "yes" : "NO");
}

// One fitted time of a matched member, a row of the times table (none when no campaign fitted it).
void time_row(const Group& g, const std::string& label, const char* time, MemberComparison& result) {
  bool made = false;
  for (const auto* m : g.in)
    if (m && m->fits.count(fit_key(time))) made = true;
  if (!made) return;
  std::vector<std::string> row{case_label(g.first->case_name), label, time};
  std::vector<const FitParameter*> params;
  for (const auto* m : g.in) {
    const FitParameter* p = nullptr;
    if (!m) {
      row.push_back("absent");
    } else {
      const ColumnValue v = column_value(m->fits, time);
      p = v.parameter;
      row.push_back(p ? pm(p->value, p->half_width()) : "n/a: " + v.reason);
    }
    params.push_back(p);
  }
  for (std::size_t c = 1; c < g.in.size(); ++c) against_first(params[0], params[c], row, result);
  result.times.rows.push_back(row);
}

void start_tables(const std::vector<CampaignFits>& campaigns, MemberComparison& result) {
  result.times.title =
      "Per-member fitted times k tau side by side (± = 95 % half-width; difference and overlap against the first "
      "campaign)";
  result.times.header = {"case", "member", "time"};
  for (const auto& c : campaigns) result.times.header.push_back(c.name);
  for (std::size_t c = 1; c < campaigns.size(); ++c) {
    result.times.header.push_back("difference " + campaigns[c].name + " - " + campaigns[0].name);
    result.times.header.push_back("95% overlap " + campaigns[c].name);
  }
  result.unmatched.title = "Members found in only some of the campaigns";
  result.unmatched.header = {"case", "member", "found", "slug"};
}

// A matched member: a row of the unmatched table where some campaign lacks it; where two or more
// hold it, its parameters that differ (outside the key) and a row per fitted time.
void compare_group(const std::vector<CampaignFits>& campaigns, const Group& g, const std::vector<std::string>& key_names,
                   std::set<std::string>& differing, MemberComparison& result) {
  const std::string label = group_label(g, key_names);
  std::vector<std::string> present;
  std::string slugs;
  for (std::size_t c = 0; c < campaigns.size(); ++c)
    if (g.in[c]) {
      present.push_back(campaigns[c].name);
      slugs += (slugs.empty() ? "" : ", ") + campaigns[c].name + ": " + g.in[c]->slug;
    }
  if (present.size() < campaigns.size()) {
    std::string found = "only in ";
    for (std::size_t i = 0; i < present.size(); ++i) found += (i ? ", " : "") + present[i];
    result.unmatched.rows.push_back({case_label(g.first->case_name), label, found, slugs});
  }
  if (present.size() < 2) return;
  for (const auto* m : g.in) {
    if (!m) continue;
    for (const auto& [n, v] : m->parameters)
      if (std::find(key_names.begin(), key_names.end(), n) == key_names.end() && !same_value(v, value_of(*g.first, n)))
        differing.insert(n);
  }
  for (const char* time : k_times) time_row(g, label, time, result);
}

}  // namespace

MemberComparison compare_members(const std::vector<CampaignFits>& campaigns) {
  MemberComparison result;
  std::vector<std::vector<Member>> members;
  std::set<std::string> names;
  for (const auto& c : campaigns) {
    members.push_back(read_members(c));
    const auto ids = identifying(c, members.back());
    names.insert(ids.begin(), ids.end());
  }
  result.match_parameters.assign(names.begin(), names.end());
  const auto& key_names = result.match_parameters;
  break_ties(members, key_names);
  const std::vector<Group> groups = match_members(members, key_names);
  start_tables(campaigns, result);
  std::set<std::string> differing;
  for (const auto& g : groups) compare_group(campaigns, g, key_names, differing, result);
  result.differing_parameters.assign(differing.begin(), differing.end());
  return result;
}

}  // namespace capsule::analysis
