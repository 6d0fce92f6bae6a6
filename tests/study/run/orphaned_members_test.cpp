// After `kill -9` of GNU Parallel (and of study), the members it started go on and hold the
// campaign's run lock (they inherit its descriptor): the next `study run` exits 5 and names
// those processes, pid and member, so the user knows what holds the lock.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "study/run/lock_holders.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("the run lock held by members a killed GNU Parallel left: the next run names them", "[study]") {
  const fs::path dir = testing::scratch_dir("orphaned_members");
  // One member of about 10 s (kt 40 at about 0.25 s per kt): long enough to be caught running.
  testing::write_text(dir / "c.json", testing::tiny_campaign("orphans", {0.05}, 40, 0.1).dump(2));
  // Its own session, so the test can kill exactly this run's process tree.
  const pid_t child = testing::start_study_run(dir);
  REQUIRE(child > 0);
  const fs::path campaign = dir / "results" / "orphans";
  // Running: GNU Parallel's pid recorded and the member's capsule writing its progress.
  long parallel_pid = 0;
  const bool running = testing::wait_for(
      [&] {
        std::ifstream in(campaign / ".running");
        const auto info = nlohmann::json::parse(in, nullptr, false);
        if (info.is_object()) parallel_pid = info.value("parallel_pid", 0L);
        bool progress = false;
        std::error_code ec;
        for (fs::directory_iterator it(campaign / "members", ec), end; !ec && it != end; it.increment(ec))
          progress = progress || fs::exists(it->path() / "member.h5.partial");
        return parallel_pid > 0 && progress;
      },
      60);
  REQUIRE(running);
  ::kill(static_cast<pid_t>(parallel_pid), SIGKILL);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);

  const auto again = testing::run_study({"run", "c.json"}, dir);
  INFO(again.output);
  CHECK(again.exit_code == 5);
  CHECK_THAT(again.output, Catch::Contains("GNU Parallel pid " + std::to_string(parallel_pid) + " (no longer running)"));
  CHECK_THAT(again.output, Catch::Contains("held by") && Catch::Contains("(capsule, member Ca0.05-") &&
                               Catch::Contains("(study, member Ca0.05-"));
  const auto holders = lock_holders(campaign / ".lock");
  CHECK_FALSE(holders.empty());
  for (const auto& h : holders) CHECK_THAT(again.output, Catch::Contains("pid " + std::to_string(h.pid) + " ("));

  // The orphans end: stopped here by their pids.
  for (const auto& h : holders) ::kill(static_cast<pid_t>(h.pid), SIGKILL);
  CHECK(testing::wait_for([&] { return lock_holders(campaign / ".lock").empty(); }, 30));
  fs::remove_all(dir);
}
