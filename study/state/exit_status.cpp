#include "study/state/exit_status.hpp"

namespace capsule::study {

int members_exit_code(const CampaignSurvey& survey) {
  if (survey.count(MemberState::failed) + survey.count(MemberState::unstable) + survey.count(MemberState::stopped) +
          survey.count(MemberState::unreadable) >
      0)
    return exit_members_failed;
  if (survey.count(MemberState::complete) < survey.members.size()) return exit_members_missing;
  return exit_ok;
}

int worst_exit_code(const std::vector<int>& codes) {
  for (int code : {exit_failure, exit_usage, exit_run_still_going, exit_members_failed, exit_members_missing})
    for (int c : codes)
      if (c == code) return code;
  return exit_ok;
}

const char* exit_status_help() {
  return "Exit status: 0 done (run/status/report: every member complete); 1 the tool failed; 2 bad campaign\n"
         "file or command line; 3 some member failed, ended unstable or stopped; 4 no member failed but some\n"
         "have not run (new, interrupted, running); 5 run: another `study run` of this campaign is going.";
}

}  // namespace capsule::study
