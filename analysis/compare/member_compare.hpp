#pragma once
// Per-member fitted times of several campaigns side by side. Members are matched
// across the campaigns' fits.json by case name and the parameters that identify a
// member within its campaign: every table's x, and every recorded parameter whose
// value varies among the members of one case (in any of the campaigns). Members that
// still share such a key within one campaign are told apart by their slug.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/report/table.hpp"

namespace capsule::analysis {

struct CampaignFits {
  std::string name;
  nlohmann::json fits;  // a parsed fits.json written by write_report
};

struct MemberComparison {
  std::vector<std::string> match_parameters;  // besides the case name, sorted
  // Recorded parameters not used for matching whose values differ between matched
  // members (e.g. a parameter changed between otherwise equal campaigns), sorted.
  std::vector<std::string> differing_parameters;
  // One row per member found in at least two campaigns and per fitted time:
  // case, member, time, value ± 95 % half-width per campaign ("n/a: <reason>" without
  // a number, "absent" where the campaign lacks the member), then per later campaign
  // the difference against the first and "yes"/"NO" for overlapping 95 % intervals.
  Table times;
  // Members missing from at least one campaign: case, member, "only in <names>", slugs.
  Table unmatched;
  int compared = 0;         // pairs of intervals compared
  int non_overlapping = 0;  // of which do not overlap
};

// Throws std::runtime_error naming the campaign when a member entry is malformed.
MemberComparison compare_members(const std::vector<CampaignFits>& campaigns);

}  // namespace capsule::analysis
