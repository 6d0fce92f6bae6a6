#include "solver/common/atomic_write.hpp"
#include "analysis/compare/campaign_compare.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analysis/fit/fit_result.hpp"
#include "analysis/compare/member_compare.hpp"
#include "analysis/report/table.hpp"
#include "analysis/compare/bilinear_entries.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

nlohmann::json read_fits_json(const CompareEntry& e) {
  const fs::path path = fs::path(e.report_dir) / "fits.json";
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot open (run the report first)");
  nlohmann::json j;
  try {
    f >> j;
  } catch (const nlohmann::json::exception& ex) {
    throw std::runtime_error(path.string() + ": not valid JSON: " + ex.what());
  }
  return j;
}

std::string pm(double v, double hw) { return plus_minus(v, hw); }

// One coefficient of the entries matched by `k`: value ± 95 % half-width per campaign, then per
// later campaign the difference against the first and whether the intervals overlap.
std::vector<std::string> coefficient_row(const std::string& k, const char* coef,
                                         const std::vector<std::map<std::string, const BilinearEntry*>>& by_key, int& status) {
  std::vector<std::string> row{k, coef};
  std::vector<const FitParameter*> params;
  for (const auto& campaign : by_key) {
    const auto it = campaign.find(k);
    const FitParameter* p = nullptr;
    if (it == campaign.end()) row.push_back("absent");
    else if (!it->second->fit.ok) row.push_back("n/a: " + it->second->fit.reason);
    else {
      p = it->second->fit.parameter(coef);
      row.push_back(pm(p->value, p->half_width()));
    }
    params.push_back(p);
  }
  for (std::size_t c = 1; c < by_key.size(); ++c) {
    if (!params[0] || !params[c]) {
      row.insert(row.end(), {"", ""});
      continue;
    }
    const bool ov = intervals_overlap(params[0]->ci_low, params[0]->ci_high, params[c]->ci_low, params[c]->ci_high);
    if (!ov) status = 1;
    row.push_back(format_number(params[c]->value - params[0]->value));
    row.push_back(ov ? "yes" : "NO");
  }
  return row;
}

// The bilinear coefficients of every campaign side by side, rows matched by (case, target), or by
// target alone when every campaign has one case; status 1 when an interval does not overlap the first
// campaign's. No rows when no report has a bilinear fit.
Table bilinear_side_by_side(const std::vector<CompareEntry>& entries, const std::vector<std::vector<BilinearEntry>>& all,
                            int& status) {
  bool one_case_each = true;
  for (const auto& campaign : all) {
    std::map<std::string, int> per_target;
    for (const auto& b : campaign) per_target[b.target]++;
    for (const auto& [t, n] : per_target)
      if (n > 1) one_case_each = false;
  }
  auto key = [&](const BilinearEntry& b) { return one_case_each ? b.target : b.case_name + " / " + b.target; };

  Table side;
  side.title = "Bilinear coefficients side by side (difference and overlap against the first campaign)";
  side.header = {"case / target", "coefficient"};
  for (const auto& e : entries) side.header.push_back(e.name);
  for (std::size_t i = 1; i < entries.size(); ++i) {
    side.header.push_back("difference " + entries[i].name + " - " + entries[0].name);
    side.header.push_back("95% overlap " + entries[i].name);
  }
  std::vector<std::string> keys;
  std::vector<std::map<std::string, const BilinearEntry*>> by_key(all.size());
  for (std::size_t c = 0; c < all.size(); ++c)
    for (const auto& b : all[c]) {
      by_key[c][key(b)] = &b;
      if (std::find(keys.begin(), keys.end(), key(b)) == keys.end()) keys.push_back(key(b));
    }
  for (const auto& k : keys)
    for (const char* coef : {"a", "b", "c"}) side.rows.push_back(coefficient_row(k, coef, by_key, status));
  return side;
}

// Per-member fitted times, matched across the campaigns (compare_members.*, and its section of
// compare.md); status 1 when an interval does not overlap.
std::string member_times_section(const std::vector<CampaignFits>& fits, const std::string& out_dir, int& status) {
  const MemberComparison mc = compare_members(fits);
  if (mc.non_overlapping > 0) status = 1;
  std::string section = "\n## Per-member fitted times\n\nMembers matched by case";
  for (std::size_t i = 0; i < mc.match_parameters.size(); ++i)
    section += (i ? ", " : " and ") + mc.match_parameters[i];
  section += mc.match_parameters.empty() ? std::string(" alone (no parameter varies within a case).")
                                         : std::string(" (the parameters that identify a member within its campaign).");
  if (!mc.differing_parameters.empty()) {
    section += " Not used for matching, but different between matched members:";
    for (std::size_t i = 0; i < mc.differing_parameters.size(); ++i)
      section += (i ? ", " : " ") + mc.differing_parameters[i];
    section += ".";
  }
  section += " " + std::to_string(mc.compared) + " pairs of 95 % intervals compared, " +
             std::to_string(mc.non_overlapping) + " do not overlap.\n\n";
  section += mc.times.rows.empty() ? std::string("No member appears in two campaigns.\n") : mc.times.to_markdown();
  section += "\n";
  section += mc.unmatched.rows.empty() ? std::string("Every member appears in every campaign.\n")
                                       : mc.unmatched.to_markdown();
  mc.times.write(out_dir, "compare_members");
  mc.unmatched.write(out_dir, "compare_members_unmatched");
  return section;
}

}  // namespace

int compare_campaigns(const std::vector<CompareEntry>& entries, std::ostream& out, const std::string& out_dir,
                      const CompareSection& extra) {
  std::vector<std::vector<BilinearEntry>> all;
  std::vector<CampaignFits> fits;
  for (const auto& e : entries) {
    fits.push_back({e.name, read_fits_json(e)});
    all.push_back(read_bilinear_entries(e.name, fits.back().fits));
  }
  int status = 0;
  const Table side = bilinear_side_by_side(entries, all, status);

  fs::create_directories(out_dir);
  std::string md = "# Campaign comparison\n\n";
  std::string csv = side.to_csv();
  if (side.rows.empty()) {
    out << "No bilinear fits in these reports (add \"bilinear\" to the analysis block).\n";
    md += "No bilinear fits in these reports.\n\n";
  } else {
    md += side.to_markdown();
    out << side.to_markdown();
  }

  if (extra) md += extra(all, status, out_dir, out);

  // Per-member fitted times need two campaigns.
  if (entries.size() > 1) {
    const std::string section = member_times_section(fits, out_dir, status);
    md += section;
    out << section;
  }
  capsule::write_file_atomically(fs::path(out_dir) / "compare.md", md);
  capsule::write_file_atomically(fs::path(out_dir) / "compare.csv", csv);
  return status;
}

}  // namespace capsule::analysis
