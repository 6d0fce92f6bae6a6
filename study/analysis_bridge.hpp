#pragma once
// `study report` and `study compare`: hand finished members to the analysis library
// (analysis/report.hpp, analysis/compare.hpp). Kept apart so the rest of study builds
// while the analysis API is being written.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "study/campaign_survey.hpp"

namespace capsule::study {

// Writes results/<campaign>/report via analysis::write_report; returns the exit status.
int report_campaign(const CampaignSurvey& survey, std::ostream& out);

// Compares the reports of several campaigns; returns analysis::compare_campaigns' status.
int compare_campaign_files(const std::vector<std::string>& campaign_files, bool against_table2,
                           const std::filesystem::path& results_dir, std::ostream& out);

}  // namespace capsule::study
