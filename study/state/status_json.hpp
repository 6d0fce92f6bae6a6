#pragma once
// `study status --json`: the same facts as the text, for scripts:
//   {"campaign", "campaign_file", "results", "members", "counts": {state: n},
//    "exit_status", "not_complete": [{"index", "dir", "id", "state", "reason"}]}
#include <nlohmann/json.hpp>

#include "study/state/campaign_survey.hpp"

namespace capsule::study {

nlohmann::json status_json(const CampaignSurvey& survey);

}  // namespace capsule::study
