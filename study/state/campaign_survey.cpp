#include "study/state/campaign_survey.hpp"

#include <fstream>
#include <sstream>

#include "study/state/member_lock.hpp"
#include "study/state/campaign_owner.hpp"
#include "study/state/member_leftovers.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

std::size_t CampaignSurvey::count(MemberState state) const {
  std::size_t n = 0;
  for (const auto& c : conditions) n += c.state == state;
  return n;
}

CampaignSurvey survey_campaign(const std::string& campaign_file, const fs::path& results_dir, const QueueReader& queue,
                               SurveyDetail detail) {
  Campaign campaign = load_campaign(campaign_file);
  ResultsLayout layout(results_dir, campaign.name);
  require_same_campaign(campaign, layout);
  require_no_linked_members_folder(layout);
  std::vector<Member> members;
  std::vector<MemberCondition> conditions;
  for_each_member(
      campaign,
      [&](Member&& m) {
        conditions.push_back(inspect_member(layout.member(m), m.id));
        if (detail == SurveyDetail::states_only) m.scene = nlohmann::json();  // the bulk of a member
        members.push_back(std::move(m));
      },
      [&](std::size_t index, const std::string& case_name) { members[index].other_cases.push_back(case_name); });
  // Members whose Slurm task waits in the queue (after an export): not new, so neither a
  // re-export nor `study run` starts them a second time.
  const QueuedMembers waiting = queue(layout);
  for (std::size_t i = 0; i < members.size(); ++i)
    if (const auto it = waiting.queued.find(members[i].dir_name()); it != waiting.queued.end())
      if (const MemberState st = conditions[i].state;
          st == MemberState::fresh || st == MemberState::interrupted || st == MemberState::failed)
        conditions[i] = MemberCondition(MemberState::queued, "waiting in Slurm's queue: " + it->second);
  CampaignSurvey survey{std::move(campaign), std::move(members), std::move(layout), std::move(conditions), waiting.note};
  return survey;
}

std::vector<std::string> members_in_progress(const CampaignSurvey& survey) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < survey.members.size(); ++i)
    if (const MemberState st = survey.conditions[i].state; st == MemberState::running || st == MemberState::interrupted)
      names.push_back(survey.members[i].dir_name());
  return names;
}

namespace {

bool can_look_into(const fs::path& dir) {
  std::error_code ec;
  (void)fs::symlink_status(dir / "scene.json", ec);
  return !ec || ec == std::errc::no_such_file_or_directory;
}

}  // namespace

void prepare_member_directories(const CampaignSurvey& survey) {
  fs::create_directories(survey.layout.members_dir());
  record_campaign(survey.campaign, survey.layout);
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    const Member& m = survey.members[i];
    const MemberPaths p = survey.layout.member(m);
    if (!linked_member_folder(p.dir).empty()) continue;  // unreadable: nothing is written through it
    // A folder it cannot look into (no permission): named in the summary, nothing written there.
    if (survey.conditions[i].state == MemberState::unreadable && !can_look_into(p.dir)) continue;
    fs::create_directories(p.dir);
    // A complete member keeps the scene.json it ran with (its member file records the scene
    // too): a pass over a finished campaign changes no committed file, even where today's
    // canonical scene spells the same member differently (a key a later version writes).
    if (survey.conditions[i].state == MemberState::complete) remove_complete_member_leftovers(p, m.id);
    if (survey.conditions[i].state == MemberState::complete && fs::exists(p.scene)) continue;
    const std::string text = m.scene.dump(2) + "\n";
    if (!fs::exists(p.scene) || read_file_text(p.scene) != text) write_file_atomically(p.scene, text);
  }
}

void clear_for_rerun(const MemberPaths& paths) {
  for (const auto& p : {paths.h5, paths.partial, paths.exit_status}) fs::remove(p);
}

std::vector<std::size_t> clear_members_to_rerun(const CampaignSurvey& survey, const std::vector<std::size_t>& to_run,
                                                bool rerun_unstable, bool rerun_stopped) {
  std::vector<std::size_t> still;
  for (std::size_t i : to_run) {
    const MemberPaths p = survey.layout.member(survey.members[i]);
    const MemberLock lock(p.dir);
    if (!lock.held()) continue;  // a live run has it: its own files say how it ends
    std::error_code ec;
    // The states that need running without a member file stay so under the lock; one that has a
    // member file now is judged again from it.
    if (fs::exists(p.h5, ec) || fs::is_symlink(p.h5, ec))
      if (!needs_run(inspect_member(p, survey.members[i].id), rerun_unstable, rerun_stopped)) continue;
    clear_for_rerun(p);  // a stale .partial or failed attempt is rerun from scratch
    still.push_back(i);
  }
  return still;
}

}  // namespace capsule::study
