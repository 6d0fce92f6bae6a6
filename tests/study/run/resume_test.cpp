// Resume: `study run` killed with SIGKILL while members run, then run again, reruns only
// the incomplete members and ends with every member complete.
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fstream>
#include <map>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "study/campaign/campaign.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// Every process of session `sid` (the run's whole process tree: study, GNU Parallel, and
// the members, which GNU Parallel puts in process groups of their own).
std::vector<pid_t> session_members(pid_t sid) {
  std::vector<pid_t> pids;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const auto close = line.rfind(')');  // the command name may hold spaces
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state;
    long ppid, pgrp, session;
    if (rest >> state >> ppid >> pgrp >> session && session == sid && state != 'Z') pids.push_back(std::stoi(name));
  }
  return pids;
}

// SIGKILL everything in the session, as a machine losing power would, until nothing is left.
void kill_session(pid_t sid) {
  for (int round = 0; round < 100; ++round) {
    const auto pids = session_members(sid);
    if (pids.empty()) return;
    for (pid_t p : pids) ::kill(p, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace

TEST_CASE("a run killed with SIGKILL resumes: only incomplete members rerun", "[study]") {
  const fs::path dir = testing::scratch_dir("resume");
  // Four members of ~1.5 s each (kt 3 + 2 at about 0.25 s per kt), two at a time.
  testing::write_text(dir / "c.json", testing::tiny_campaign("resume", {0.01, 0.02, 0.03, 0.04}, 3, 2).dump(2));

  // Its own session, so the test can kill exactly this run's process tree.
  const pid_t child = testing::start_study_run(dir, {"--jobs", "2"});
  REQUIRE(child > 0);

  const CampaignSurvey before = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  // Wait until at least one member is complete and another is mid-run (its .partial exists),
  // then kill. 60 s bounds a stuck run; the members need about 3 s in all.
  bool mid_run = false;
  for (int i = 0; i < 3000 && !mid_run; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    int complete = 0, partial = 0;
    for (const auto& m : before.members) {
      const MemberPaths p = before.layout.member(m);
      complete += fs::exists(p.h5);
      partial += fs::exists(p.partial);
    }
    mid_run = complete >= 1 && partial >= 1;
  }
  kill_session(child);
  int status = 0;
  ::waitpid(child, &status, 0);
  REQUIRE(mid_run);

  const CampaignSurvey killed = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  std::map<std::string, fs::file_time_type> complete_before;
  std::size_t incomplete = 0;
  for (std::size_t i = 0; i < killed.members.size(); ++i) {
    if (killed.conditions[i].state == MemberState::complete)
      complete_before[killed.members[i].id] = fs::last_write_time(killed.layout.member(killed.members[i]).h5);
    else
      ++incomplete;
  }
  REQUIRE(!complete_before.empty());
  REQUIRE(incomplete >= 1);
  CHECK(killed.count(MemberState::interrupted) >= 1);

  const auto rerun = testing::run_study({"run", "c.json"}, dir);
  INFO(rerun.output);
  CHECK(rerun.exit_code == 0);
  CHECK(rerun.output.find("running " + std::to_string(incomplete) + " of 4 members") != std::string::npos);

  const CampaignSurvey after = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK(after.count(MemberState::complete) == 4);
  for (const auto& m : after.members) {
    const MemberPaths p = after.layout.member(m);
    CHECK_FALSE(fs::exists(p.partial));
    if (complete_before.count(m.id)) CHECK(fs::last_write_time(p.h5) == complete_before[m.id]);  // not rerun
  }

  // A third run has nothing to do.
  const auto third = testing::run_study({"run", "c.json"}, dir);
  CHECK(third.exit_code == 0);
  CHECK(third.output.find("nothing to run") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("after kill -9 of study, the next run says the run is still going, with pids and members", "[study]") {
  const fs::path dir = testing::scratch_dir("still_going");
  // One member of about 7 s (kt 20 + 8): still running when study is killed.
  testing::write_text(dir / "c.json", testing::tiny_campaign("still_going", {0.05}, 20, 8).dump(2));
  // Its own session, so the test can kill exactly this run's process tree.
  const pid_t child = testing::start_study_run(dir);
  REQUIRE(child > 0);
  const CampaignSurvey before = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const MemberPaths p = before.layout.member(before.members[0]);
  bool running = false;
  for (int i = 0; i < 3000 && !running; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    running = fs::exists(p.partial);
  }
  ::kill(child, SIGKILL);  // study only: GNU Parallel and the member go on
  int status = 0;
  ::waitpid(child, &status, 0);
  REQUIRE(running);

  const auto again = testing::run_study({"run", "c.json"}, dir);
  INFO(again.output);
  CHECK(again.exit_code == 5);
  CHECK(again.output.find("still going") != std::string::npos);
  CHECK(again.output.find("study pid " + std::to_string(child) + " (no longer running)") != std::string::npos);
  CHECK(again.output.find("GNU Parallel pid ") != std::string::npos);
  CHECK(again.output.find("(running)") != std::string::npos);
  CHECK(again.output.find("1 member running: " + before.members[0].dir_name()) != std::string::npos);
  kill_session(child);
  fs::remove_all(dir);
}

TEST_CASE("a run over a complete campaign leaves its members' scene.json as they are", "[study]") {
  // A shipped member's scene.json may spell the same member otherwise than today's canonical
  // scene does (a key a later version adds); a pass that finds nothing to run changes no file.
  const fs::path dir = testing::scratch_dir("complete_scene_kept");
  testing::write_text(dir / "c.json", testing::tiny_campaign("complete_scene_kept", {0.05}, 0.2, 0).dump());
  const auto first = testing::run_study({"run", "c.json"}, dir);
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  const CampaignSurvey survey = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const fs::path scene = survey.layout.member(survey.members[0]).scene;
  const std::string shipped = testing::read_text(scene) + "\n";  // as another version wrote it
  testing::write_text(scene, shipped);
  const auto again = testing::run_study({"run", "c.json"}, dir);
  INFO(again.output);
  CHECK(again.exit_code == 0);
  CHECK(again.output.find("nothing to run") != std::string::npos);
  CHECK(testing::read_text(scene) == shipped);
  fs::remove_all(dir);
}
