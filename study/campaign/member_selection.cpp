#include "study/campaign/member_selection.hpp"

#include <algorithm>
#include <stdexcept>

#include "study/campaign/campaign_error.hpp"

namespace capsule::study {

bool MemberSelection::selects(const Member& m) const {
  if (!scene_matches(m.scene, where)) return false;
  if (cases.empty()) return true;
  return std::any_of(cases.begin(), cases.end(), [&m](const std::string& name) {
    return m.case_name == name || std::find(m.other_cases.begin(), m.other_cases.end(), name) != m.other_cases.end();
  });
}

MemberSelection select_members(const std::string& campaign_file, const Campaign& campaign,
                               const std::vector<std::string>& cases, const std::vector<std::string>& where) {
  MemberSelection s;
  for (const auto& name : cases) {
    std::string known;
    bool found = false;
    for (const auto& c : campaign.cases) {
      known += (known.empty() ? "" : ", ") + c.name;
      found = found || c.name == name;
    }
    if (!found)
      throw campaign_error(campaign_file, "cases", "--case \"" + name + "\" names no case of this campaign",
                           known.empty() ? "no --case: this campaign has no cases" : "one of: " + known);
    s.cases.push_back(name);
  }
  for (const auto& text : where) {
    try {
      s.where.push_back(parse_scene_condition(text));
    } catch (const std::invalid_argument& e) {
      throw campaign_error(campaign_file, "--where", e.what(), "KEY=VALUE with a dotted scene key");
    }
  }
  return s;
}

void require_matches(const std::string& campaign_file, const MemberSelection& selection, const std::vector<bool>& matched) {
  for (std::size_t i = 0; i < selection.where.size(); ++i)
    if (i >= matched.size() || !matched[i])
      throw campaign_error(campaign_file, "--where", "\"" + selection.where[i].text + "\" matches no member of this campaign",
                           "a dotted key of the canonical scene (capsule check) and a value some member has");
}

}  // namespace capsule::study
