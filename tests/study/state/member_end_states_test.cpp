// What a member's leftover files say once its run ended without a member file
// (study/state/member_state.hpp): a kill with a restart point is resumable, not failed, and a
// progress file naming a pid that a younger process reuses is not a running member.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "study/state/member_state.hpp"
#include "study/state/run_record.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("a member killed by a signal is interrupted, not failed - a crash is a failure", "[study]") {
  const fs::path dir = testing::scratch_dir("killed_member");
  const MemberPaths p = member_paths_in(dir);
  testing::write_text(p.exit_status, "137\n");
  testing::write_text(p.log, "capsule: restart point at step 40\n");
  SECTION("with a restart point") {
    testing::write_text(p.restart, "restart");
    const MemberCondition c = inspect_member(p, "id");
    CHECK(c.state == MemberState::interrupted);
    CHECK_THAT(c.reason, Catch::Contains("killed by signal 9") && Catch::Contains("continues it from its restart point"));
  }
  SECTION("without one: interrupted all the same (killed from outside), run again from the start") {
    testing::write_text(p.partial, "partial");
    const MemberCondition c = inspect_member(p, "id");
    CHECK(c.state == MemberState::interrupted);
    CHECK_THAT(c.reason, Catch::Contains("killed by signal 9 before its first restart point") &&
                             Catch::Contains("runs it again from the start"));
  }
  SECTION("a signal the solver raised itself (SIGSEGV) is a failure") {
    testing::write_text(p.exit_status, "139\n");
    CHECK(inspect_member(p, "id").state == MemberState::failed);
  }
  fs::remove_all(dir);
}

TEST_CASE("a progress file naming a live pid of this host that started after the file was written is not running",
          "[study]") {
  const fs::path dir = testing::scratch_dir("reused_progress_pid");
  const MemberPaths p = member_paths_in(dir);
  testing::write_text(p.partial, "partial");
  // The progress file names this test's own (live) pid.
  const nlohmann::json progress = {{"pid", static_cast<long>(::getpid())}, {"host", host_name()}, {"phase", "shear"},
                                   {"kt", 3.0}, {"member_end_kt", 10.0}, {"member_end_is_cap", false},
                                   {"steps_per_second", 10.0}, {"eta_member_seconds", 5.0}};
  testing::write_text(p.progress, progress.dump());
  // Written now by this (live) process: running.
  fs::last_write_time(p.partial, fs::file_time_type::clock::now() - std::chrono::hours(1));
  CHECK(inspect_member(p, "id").state == MemberState::running);
  // Written six days before this process started: another process that had the pid then.
  fs::last_write_time(p.progress, fs::file_time_type::clock::now() - std::chrono::hours(24 * 6));
  CHECK(inspect_member(p, "id").state == MemberState::interrupted);
  fs::remove_all(dir);
}
