#pragma once
// `study compare` reads each campaign's report/fits.json. A report written before some of
// its members were (re)run describes old results: say so, naming the newest member file.
#include <optional>
#include <string>

#include "study/state/campaign_survey.hpp"

namespace capsule::study {

// A warning line when report/fits.json is older than a member file (or the report is
// missing); nothing when the report is up to date.
std::optional<std::string> stale_report_warning(const CampaignSurvey& survey);

}  // namespace capsule::study
