#pragma once
// The exit status of `study` (docs/guide/campaigns.md "Exit status", `study --help`):
//   0  done; for run, status and report: every member complete
//   1  the tool itself failed (a file could not be written, GNU Parallel missing, ...)
//   2  bad campaign file or command line (nothing was run)
//   3  run, status, report: some member failed, ended unstable or stopped
//   4  status, report: no member failed, but some have not run (new, interrupted or running)
//   5  run: another `study run` of this campaign is still going
#include <vector>

#include "study/state/campaign_survey.hpp"

namespace capsule::study {

inline constexpr int exit_ok = 0;
inline constexpr int exit_failure = 1;
inline constexpr int exit_usage = 2;
inline constexpr int exit_members_failed = 3;
inline constexpr int exit_members_missing = 4;
inline constexpr int exit_run_still_going = 5;

// 0, 3 or 4 from the members' states, as above.
int members_exit_code(const CampaignSurvey& survey);

// The exit status of several campaigns run one after another: 1 if the tool failed for any, else
// 5, 3, 4 in that order (a run still going, a member failed, members not run), else 0.
int worst_exit_code(const std::vector<int>& codes);

// The text of the table above, for --help.
const char* exit_status_help();

}  // namespace capsule::study
