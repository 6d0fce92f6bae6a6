#pragma once
// `study report` and `study compare`: hand finished members to the analysis library
// (analysis/report/report.hpp, analysis/compare/campaign_compare.hpp, analysis/dissertation/report.hpp).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "study/state/campaign_survey.hpp"

namespace capsule::study {

// The help of `--legacy-member-files` (report, thesis): io::accept_files_without_content_hash.
inline constexpr const char* legacy_member_files_help =
    "also read member files without a content hash (written before it existed); their content cannot be checked";

struct ReportOptions {
  bool partial = false;  // write the report even when some member files cannot be read (PARTIAL.md names them)
};

// Writes results/<campaign>/report via analysis::write_report, into a staging folder that is
// swapped in when complete; returns the exit status. When a member file cannot be read (locked,
// damaged, a checksum or content hash that does not match) the previous report is kept and it
// returns 3, unless options.partial.
int report_campaign(const CampaignSurvey& survey, const ReportOptions& options, std::ostream& out);

// Compares the reports of several campaigns; returns analysis::compare_campaigns' status.
int compare_campaign_files(const std::vector<std::string>& campaign_files, bool against_table2,
                           const std::filesystem::path& results_dir, std::ostream& out);

// Writes THESIS.md (analysis::write_dissertation) from the shipped results under results_dir:
// Table 2, the ratios b/a and the claims of Chapters 3-5 against the dissertation. Prints
// the counts; returns 0 (campaigns not run give "cannot tell", not an error).
int write_dissertation_comparison(const std::filesystem::path& results_dir, const std::filesystem::path& out_file,
                            std::ostream& out);

}  // namespace capsule::study
