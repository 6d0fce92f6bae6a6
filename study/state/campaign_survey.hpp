#pragma once
// A campaign file read, expanded, and matched against what its results folder holds:
// the common first step of plan, run, status, export and report. Read-only.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "study/campaign/campaign.hpp"
#include "study/campaign/expansion.hpp"
#include "study/state/member_state.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

struct CampaignSurvey {
  Campaign campaign;
  std::vector<Member> members;
  ResultsLayout layout;
  std::vector<MemberCondition> conditions;  // one per member
  std::string note;                         // what could not be known (squeue failed), "" when all was

  std::size_t count(MemberState state) const;
};

// What a survey keeps of each member: everything, or (for `study status`, which reads only
// states) the member without its scene, so a 10^5-member campaign's status fits in little memory.
enum class SurveyDetail { full, states_only };

// The members whose batch job waits in a queue, read from the results folder's layout; the
// caller passes the reader (Slurm's: slurm_queue, study/slurm/slurm_queue.hpp).
struct QueuedMembers {
  std::map<std::string, std::string> queued;  // member folder name -> "job NAME task T (STATE)"
  std::string note;                            // why the queue could not be asked ("" when it was, or no export)
};
using QueueReader = std::function<QueuedMembers(const ResultsLayout&)>;

// A queued member that is fresh, interrupted or failed is `queued`: neither a re-export nor
// `study run` starts it a second time.
CampaignSurvey survey_campaign(const std::string& campaign_file, const std::filesystem::path& results_dir,
                               const QueueReader& queue, SurveyDetail detail = SurveyDetail::full);

// The folder names of the members that have a run in progress or an interrupted one (a
// .partial or restart point and no member file): under a held run lock, the running ones.
std::vector<std::string> members_in_progress(const CampaignSurvey& survey);

// Creates every member directory and writes its scene.json (when missing or different),
// and records the campaign file as run (campaign.json).
void prepare_member_directories(const CampaignSurvey& survey);

// Clears what a rerun replaces: member.h5 (if not complete), .partial, exit_status. The log is
// kept (the rerun appends to it) and so is member.h5.restart, from which the rerun continues.
void clear_for_rerun(const MemberPaths& paths);

// Clears, for each member of `to_run` (indices into survey.members), what a rerun replaces; each
// under the member's lock (member_lock.hpp) and after reading its member file again, since a Slurm
// task or another run may have finished or started it since the survey: a member whose lock
// another live process holds, or that no longer needs running, is left as it is. Returns the
// members still to run, in order.
std::vector<std::size_t> clear_members_to_rerun(const CampaignSurvey& survey, const std::vector<std::size_t>& to_run,
                                                bool rerun_unstable, bool rerun_stopped);

}  // namespace capsule::study
