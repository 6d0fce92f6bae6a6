#include "study/state/status_json.hpp"

#include "study/state/exit_status.hpp"

namespace capsule::study {

nlohmann::json status_json(const CampaignSurvey& survey) {
  nlohmann::json counts = nlohmann::json::object();
  for (auto state : kAllMemberStates)
    counts[state_name(state)] = survey.count(state);
  nlohmann::json not_complete = nlohmann::json::array();
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    const auto& c = survey.conditions[i];
    if (c.state == MemberState::complete) continue;
    not_complete.push_back({{"index", i},
                            {"dir", survey.members[i].dir_name()},
                            {"id", survey.members[i].id},
                            {"state", state_name(c.state)},
                            {"reason", c.reason}});
  }
  return {{"campaign", survey.campaign.name},
          {"campaign_file", survey.campaign.source},
          {"results", survey.layout.root.string()},
          {"members", survey.members.size()},
          {"counts", counts},
          {"exit_status", members_exit_code(survey)},
          {"not_complete", not_complete}};
}

}  // namespace capsule::study
