// A member runs at most once at a time and never after it is complete, whichever engine starts
// it (study/state/member_lock.hpp, study/run/member_job.hpp); a stop by signal leaves a restart point that
// the next run continues from.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/state/member_lock.hpp"
#include "study/state/run_record.hpp"
#include "study/run/shell_quote.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

using capsule::study::testing::set_age;
using capsule::study::testing::wait_for;

namespace {

// `study run-member DIR 1` as the wrapper runs it, started in the background; returns its pid.
pid_t start_run_member(const fs::path& member_dir) {
  const pid_t child = ::fork();
  if (child == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    const std::string study = testing::study_binary().string(), capsule = testing::capsule_binary().string();
    ::execl(study.c_str(), study.c_str(), "run-member", "--capsule", capsule.c_str(), member_dir.c_str(), "1",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return child;
}

testing::CommandResult run_member_now(const fs::path& member_dir) {
  return testing::run_shell(shell_quote(testing::study_binary().string()) + " run-member --capsule " +
                            shell_quote(testing::capsule_binary().string()) + " " + shell_quote(member_dir.string()) +
                            " 1 </dev/null");
}

}  // namespace

TEST_CASE("a member already running is left alone, a complete one is never rerun or rewritten", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("member_lock");
  // Long enough (several seconds) to be caught running.
  testing::write_text(dir / "c.json", testing::tiny_campaign("lock", {0.02}, 30, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);

  const pid_t first = start_run_member(p.dir);
  REQUIRE(wait_for([&] { return live_lock_owner(p.dir).has_value(); }, 10));
  // A second start of the same member (a duplicate submission, a second `study run` elsewhere).
  const auto second = run_member_now(p.dir);
  INFO(second.output);
  CHECK(second.exit_code == 0);
  CHECK(second.output.find("is running on " + host_name()) != std::string::npos);
  CHECK(second.output.find("left alone") != std::string::npos);
  s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK(s.conditions[0].state == MemberState::running);

  int status = 0;
  ::waitpid(first, &status, 0);
  CHECK(WEXITSTATUS(status) == 0);
  REQUIRE(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  CHECK_FALSE(fs::exists(member_lock_file(p.dir)));
  const std::string before = testing::read_text(p.h5);
  const auto stat_before = fs::last_write_time(p.h5);

  // A stale resubmission of the complete member runs nothing and leaves its file as it was.
  const auto again = run_member_now(p.dir);
  INFO(again.output);
  CHECK(again.exit_code == 0);
  CHECK(again.output.find("is complete: nothing run") != std::string::npos);
  CHECK(testing::read_text(p.h5) == before);
  CHECK(fs::last_write_time(p.h5) == stat_before);
  fs::remove_all(dir);
}

TEST_CASE("a stale member lock is taken over - another host's lock holds while it is touched", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("stale_lock");
  const fs::path lock_file = member_lock_file(dir);
  SECTION("this host, a pid that is not alive") {
    testing::write_text(lock_file, R"({"host": ")" + host_name() + R"(", "pid": 999999999, "started": "x"})");
    const MemberLock lock(dir);
    CHECK(lock.held());
  }
  SECTION("another host, touched recently: held") {
    testing::write_text(lock_file, R"({"host": "node-elsewhere", "pid": 12, "started": "x"})");
    const MemberLock lock(dir);
    CHECK_FALSE(lock.held());
    CHECK(lock.owner().host == "node-elsewhere");
  }
  SECTION("another host, silent for longer than kStaleSeconds: stale") {
    testing::write_text(lock_file, R"({"host": "node-elsewhere", "pid": 12, "started": "x"})");
    set_age(lock_file, 200);
    const MemberLock lock(dir);
    CHECK(lock.held());
  }
  SECTION("held by this process: a second lock is refused, and it is released at the end") {
    {
      const MemberLock first(dir);
      REQUIRE(first.held());
      const MemberLock second(dir);
      CHECK_FALSE(second.held());
      CHECK(second.owner().pid == static_cast<long>(::getpid()));
    }
    CHECK_FALSE(fs::exists(lock_file));
  }
  fs::remove_all(dir);
}

TEST_CASE("SIGTERM to a running member writes a restart point - the next run continues it", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("member_sigterm");
  testing::write_text(dir / "c.json", testing::tiny_campaign("sigterm", {0.02}, 30, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);
  const pid_t run = start_run_member(p.dir);
  // Once the member has written rows, stop it as Slurm's time limit or scancel would.
  REQUIRE(wait_for([&] { return fs::exists(p.partial) && fs::exists(p.progress); }, 20));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(run, SIGTERM);
  int status = 0;
  ::waitpid(run, &status, 0);
  CHECK(WIFEXITED(status));
  REQUIRE(fs::exists(p.restart));
  CHECK_FALSE(fs::exists(p.exit_status));  // not an end
  CHECK(testing::read_text(p.log).find("stopped by signal 15") != std::string::npos);
  s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  CHECK(s.conditions[0].state == MemberState::interrupted);

  const auto again = run_member_now(p.dir);
  INFO(again.output);
  CHECK(again.exit_code == 0);
  CHECK(testing::read_text(p.log).find("continuing from the restart point") != std::string::npos);
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  fs::remove_all(dir);
}
