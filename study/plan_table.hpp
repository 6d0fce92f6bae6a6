#pragma once
// `study plan`: one line per member (index, state, directory, swept parameters, cost)
// and the totals. Changes nothing.
#include <ostream>

#include "study/campaign_survey.hpp"

namespace capsule::study {

void print_plan(const CampaignSurvey& survey, std::ostream& out);

}  // namespace capsule::study
