// A member's lock is held while its owner keeps its heartbeat, on this host too, and only by the
// process that took it (study/state/member_lock.hpp): an owner stopped long enough to lose it backs
// off when it wakes, without touching the member's files (solver/io/write_guard.hpp), and the
// member is continued later from its restart point, not lost.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <map>
#include <thread>

#include "study/state/member_lock.hpp"
#include "study/run/shell_quote.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/state/results_layout.hpp"
#include "study/state/run_record.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

using capsule::study::testing::set_age;
using capsule::study::testing::wait_for;

namespace {

// Every file of the member folder but temporaries, with its content.
std::map<std::string, std::string> member_files(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp") == std::string::npos) files[name] = testing::read_text(e.path());
  }
  return files;
}

// The lock as another host's run-member writes it when it takes the member over.
void take_over_from_another_host(const fs::path& member_dir) {
  write_file_atomically(member_lock_file(member_dir),
                        R"({"host": "node-b", "pid": 4242, "started": "2026-12-07T00:00:00Z", "token": "node-b-token"})"
                        "\n");
}

}  // namespace

TEST_CASE("a stopped member owner whose lock was taken over backs off without touching the member, which is not lost",
          "[study][lock]") {
  const fs::path dir = testing::scratch_dir("lock_takeover");
  testing::write_text(dir / "c.json", testing::tiny_campaign("takeover", {0.02}, 30, 0).dump());
  CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  prepare_member_directories(s);
  const MemberPaths p = s.layout.member(s.members[0]);

  const pid_t owner = ::fork();
  if (owner == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen((dir / "run_member.out").c_str(), "w", stderr);
    const std::string study = testing::study_binary().string(), capsule = testing::capsule_binary().string();
    ::execl(study.c_str(), study.c_str(), "run-member", "--capsule", capsule.c_str(), "--checkpoint-seconds", "0.5",
            "--", p.dir.c_str(), "1", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Running, with a restart point written: stop the owner and its capsule (SIGSTOP, a frozen node).
  REQUIRE(wait_for([&] { return fs::exists(p.restart) && read_progress(p.progress).present; }, 30));
  const long capsule = read_progress(p.progress).pid;
  REQUIRE(capsule > 0);
  ::kill(static_cast<pid_t>(capsule), SIGSTOP);
  ::kill(owner, SIGSTOP);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  // Silent past the lock's staleness, it is taken over by another host's run of the member.
  take_over_from_another_host(p.dir);
  const auto before = member_files(p.dir);

  ::kill(static_cast<pid_t>(capsule), SIGCONT);
  ::kill(owner, SIGCONT);
  int status = 0;
  REQUIRE(wait_for([&] { return ::waitpid(owner, &status, WNOHANG) == owner; }, 30));
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(::kill(static_cast<pid_t>(capsule), 0) != 0);  // the capsule ended too
  const std::string said = testing::read_text(dir / "run_member.out") + testing::read_text(p.log);
  INFO(said);
  CHECK_THAT(said, Catch::Contains("taken over") && Catch::Contains("node-b"));
  // Nothing of the member changed: no member file, no exit status, the new owner's lock kept.
  // capsule.log (shared by every run of the member) only gained the lines that say why it stopped.
  auto after = member_files(p.dir);
  CHECK(after.at("capsule.log").rfind(before.at("capsule.log"), 0) == 0);
  after.at("capsule.log") = before.at("capsule.log");
  CHECK(after == before);
  CHECK_FALSE(fs::exists(p.h5));
  CHECK_FALSE(fs::exists(p.exit_status));
  CHECK_THAT(testing::read_text(member_lock_file(p.dir)), Catch::Contains("node-b-token"));

  // The new owner gone (its lock removed), the member continues from the restart point and completes.
  fs::remove(member_lock_file(p.dir));
  const auto again = testing::run_shell(shell_quote(testing::study_binary().string()) + " run-member --capsule " +
                                        shell_quote(testing::capsule_binary().string()) + " -- " +
                                        shell_quote(p.dir.string()) + " 1 </dev/null");
  INFO(again.output);
  CHECK(again.exit_code == 0);
  CHECK_THAT(testing::read_text(p.log), Catch::Contains("continuing from the restart point"));
  CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).conditions[0].state == MemberState::complete);
  fs::remove_all(dir);
}

TEST_CASE("a lock holder knows when its lock was taken over, and then neither touches nor removes it", "[study][lock]") {
  const fs::path dir = testing::scratch_dir("lock_token");
  {
    const MemberLock lock(dir);
    REQUIRE(lock.held());
    CHECK(lock.still_held());
    CHECK(lock.refresh());
    take_over_from_another_host(dir);
    set_age(member_lock_file(dir), 5);
    const auto mtime = fs::last_write_time(member_lock_file(dir));
    CHECK_FALSE(lock.still_held());
    CHECK_FALSE(lock.refresh());  // the heartbeat of a lost lock touches nothing
    CHECK(fs::last_write_time(member_lock_file(dir)) == mtime);
  }
  // Released at the end only when it is still ours.
  CHECK_THAT(testing::read_text(member_lock_file(dir)), Catch::Contains("node-b-token"));
  fs::remove_all(dir);
}

TEST_CASE("a lock naming a live but reused pid of this host is stale: by its heartbeat and by the process's start",
          "[study][lock]") {
  const fs::path dir = testing::scratch_dir("reused_pid");
  const fs::path lock_file = member_lock_file(dir);
  SECTION("six days without a heartbeat, naming a live process (pid 1)") {
    testing::write_text(lock_file, R"({"host": ")" + host_name() + R"(", "pid": 1, "started": "2026-12-01T00:00:00Z"})");
    set_age(lock_file, 6 * 86400);
    REQUIRE(::kill(1, 0) == 0);
    CHECK_FALSE(live_lock_owner(dir).has_value());
    const MemberLock lock(dir);
    CHECK(lock.held());
  }
  SECTION("a fresh heartbeat, but the pid's process started at another time than the lock's owner") {
    testing::write_text(lock_file, R"({"host": ")" + host_name() + R"(", "pid": )" + std::to_string(::getpid()) +
                                       R"(, "started": "x", "process_start": 1})");
    CHECK_FALSE(live_lock_owner(dir).has_value());
    const MemberLock lock(dir);
    CHECK(lock.held());
  }
  SECTION("the owner itself, with its heartbeat: held") {
    const MemberLock first(dir);
    REQUIRE(first.held());
    REQUIRE(live_lock_owner(dir).has_value());
    CHECK(live_lock_owner(dir)->pid == static_cast<long>(::getpid()));
  }
  fs::remove_all(dir);
}
