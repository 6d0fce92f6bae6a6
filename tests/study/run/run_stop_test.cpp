// `study run A.json B.json` stopped by SIGTERM (a scheduler's time limit, `kill`) stops there:
// the running campaign's members get their restart points and no later campaign starts.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/state/exit_status.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// `study run ARGS...` started in `dir` with CAPSULE_BIN = `capsule`, its output into `log`;
// returns its pid, for the test to signal and wait for.
pid_t start_study_run(const fs::path& dir, const fs::path& log, const fs::path& capsule,
                      const std::vector<std::string>& args) {
  const pid_t study = ::fork();
  if (study == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::setenv("CAPSULE_BIN", capsule.c_str(), 1);
    const std::string bin = testing::study_binary().string();
    std::vector<std::string> words{bin, "run"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    ::execv(bin.c_str(), argv.data());
    ::_exit(127);
  }
  return study;
}

}  // namespace

TEST_CASE("SIGTERM to study run stops it: the campaigns after the running one are not started", "[study]") {
  const fs::path dir = testing::scratch_dir("run_stop");
  // The first member runs for many seconds (kt 30 at about 0.25 s per kt), so the signal finds it running.
  testing::write_text(dir / "first.json", testing::tiny_campaign("stop_first", {0.02}, 30, 0).dump());
  testing::write_text(dir / "second.json", testing::tiny_campaign("stop_second", {0.02}, 0.3, 0).dump());
  const fs::path log = dir / "study.log";
  const pid_t study = start_study_run(dir, log, testing::capsule_binary(), {"first.json", "second.json", "-j", "1"});
  const CampaignSurvey first = survey_campaign((dir / "first.json").string(), dir / "results", slurm_queue);
  const MemberPaths p = first.layout.member(first.members[0]);
  bool running = false;
  for (int i = 0; i < 3000 && !running; ++i) {  // up to 30 s for GNU Parallel and capsule to start
    running = fs::exists(p.partial) && fs::exists(p.progress);
    if (!running) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(running);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(study, SIGTERM);
  int status = 0;
  ::waitpid(study, &status, 0);
  const std::string output = testing::read_text(log);
  INFO(output);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == exit_members_missing);
  CHECK_THAT(output, Catch::Contains("stopped by signal 15 (SIGTERM): 1 campaign not started: second.json"));
  const CampaignSurvey second = survey_campaign((dir / "second.json").string(), dir / "results", slurm_queue);
  CHECK_FALSE(fs::exists(second.layout.member(second.members[0]).h5));
  CHECK_FALSE(fs::exists(second.layout.member(second.members[0]).partial));
  // The stopped member can continue: it was interrupted, not ended.
  CHECK(survey_campaign((dir / "first.json").string(), dir / "results", slurm_queue).conditions[0].state ==
        MemberState::interrupted);
  fs::remove_all(dir);
}

TEST_CASE("a stopped member is given time to write its restart point before it is killed", "[study]") {
  // A stand-in capsule whose restart point takes 2 s to write and which ignores further TERMs
  // while it writes (as a capsule busy in HDF5 does not stop early). GNU Parallel's default stop
  // sequence would KILL it 350 ms after the first TERM and the point would be lost.
  const fs::path dir = testing::scratch_dir("run_stop_grace");
  testing::write_text(dir / "c.json", testing::tiny_campaign("stop_grace", {0.02}, 30, 0).dump());
  const fs::path started = dir / "started";
  const fs::path written = dir / "restart-written";
  testing::write_text(dir / "slow-capsule",
                      "#!/bin/sh\n[ \"$1\" = version ] && exec '" + testing::capsule_binary().string() +
                          "' version\n"
                          "trap 'trap \"\" TERM; sleep 2; : > \"" + written.string() + "\"; exit 4' TERM\n"
                          ": > \"" + started.string() + "\"\n"
                          "while :; do sleep 0.05; done\n");
  fs::permissions(dir / "slow-capsule", fs::perms::owner_all);
  const fs::path log = dir / "study.log";
  const pid_t study = start_study_run(dir, log, dir / "slow-capsule", {"c.json", "-j", "1"});
  bool running = false;
  for (int i = 0; i < 3000 && !running; ++i) {  // up to 30 s for GNU Parallel and the stand-in to start
    running = fs::exists(started);
    if (!running) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(running);
  ::kill(study, SIGTERM);
  int status = 0;
  ::waitpid(study, &status, 0);
  const std::string output = testing::read_text(log);
  INFO(output);
  CHECK(fs::exists(written));
  CHECK_THAT(output, Catch::Contains("stopped by signal 15"));
  fs::remove_all(dir);
}
