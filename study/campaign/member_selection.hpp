#pragma once
// `--case NAME` and `--where KEY=VALUE` of `study run` and `study plan`: the members a command
// acts on. Every --case must name a case of the campaign and every --where must parse and match
// at least one member, or the command is refused naming the campaign file and the option.
#include <string>
#include <vector>

#include "study/campaign/campaign.hpp"
#include "study/campaign/expansion.hpp"
#include "study/campaign/member_filter.hpp"

namespace capsule::study {

struct MemberSelection {
  std::vector<std::string> cases;
  std::vector<SceneCondition> where;
  bool everything() const { return cases.empty() && where.empty(); }
  // The member is of one of the cases (when any are given) and its scene meets every --where.
  bool selects(const Member& m) const;
};

// Parses the options and checks every --case against the campaign's cases; throws
// CampaignError naming `campaign_file`. Whether each --where matches a member is checked by
// require_matches once the members are known.
MemberSelection select_members(const std::string& campaign_file, const Campaign& campaign,
                               const std::vector<std::string>& cases, const std::vector<std::string>& where);

// Refuses a --where that matches no member of `members_matched` (one flag per condition, set by
// the caller while it visits the members).
void require_matches(const std::string& campaign_file, const MemberSelection& selection,
                     const std::vector<bool>& matched);

}  // namespace capsule::study
