// Nothing corrupt passes as complete, nothing complete is deleted, no path runs code: the
// fault-and-bad-input audit's defects, one test each, through the real binaries.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <hdf5.h>

#include "build_info.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/run/provenance.hpp"
#include "study/state/results_layout.hpp"
#include "study/run/run_lock.hpp"
#include "study/run/shell_quote.hpp"
#include "study/state/status_json.hpp"
#include "tests/study/support/study_test_support.hpp"
#include "tests/support/hdf5_damage.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// Every file under dir named PWNED<n> (what a hostile path would create if it ran).
std::vector<fs::path> pwned_files(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().rfind("PWNED", 0) == 0) found.push_back(e.path());  // not the folders named after them
  return found;
}

// Holds an exclusive flock on a file, as HDF5's file locking does for a process that has the
// file open for writing; released at scope exit.
struct HeldLock {
  int fd = -1;
  explicit HeldLock(const fs::path& file) : fd(::open(file.c_str(), O_RDONLY)) { ::flock(fd, LOCK_EX); }
  ~HeldLock() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

TEST_CASE("hostile results paths reach GNU Parallel and the Slurm script only as data", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("hostile_paths");
  testing::write_text(dir / "c.json", testing::tiny_campaign("hostile", {0.02, 0.03}, 0.3, 0).dump());
  // Each would run code or break the command if it reached GNU Parallel's template or a shell.
  const std::vector<std::string> paths{"R{=system(\"touch\",\"PWNED1\")=}",
                                       "R{}",
                                       "R{/}x",
                                       "R{#}{%}{.}",
                                       "R$(touch PWNED2)",
                                       "R`touch PWNED3`",
                                       "R'\"q",
                                       "-R leading dash",  // passed as --results=-R...
                                       "R;touch PWNED4;"};
  for (const auto& results : paths) {
    INFO(results);
    const auto run = testing::run_study({"run", "c.json", "--results=" + results}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 0);
    const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / results, slurm_queue);
    CHECK(s.count(MemberState::complete) == 2);

    // The Slurm script of the same folder: valid bash, and its task runs a member there.
    const auto exported = testing::run_study({"export", "c.json", "--slurm", "--results=" + results}, dir);
    INFO(exported.output);
    if (results.find('"') != std::string::npos) {  // an #SBATCH --output line cannot quote it: refused
      CHECK(exported.exit_code == 2);
      CHECK(exported.output.find("which an #SBATCH line cannot quote") != std::string::npos);
      continue;
    }
    CHECK(exported.exit_code == 0);
    const fs::path script = s.layout.slurm_dir() / "capsule.sbatch";
    CHECK(testing::run_shell("bash -n " + shell_quote(script.string())).exit_code == 0);
  }
  // A line break is refused before anything is written (no script can quote it safely).
  const auto refused = testing::run_study({"run", "c.json", "--results", "R\ntouch PWNED5"}, dir);
  CHECK(refused.exit_code == 2);
  CHECK(refused.output.find("control character") != std::string::npos);
  // A hosts file whose path holds a replacement string.
  testing::write_text(dir / "fake-ssh", "#!/bin/sh\nshift\n[ \"$1\" = \"--\" ] && shift\nexec sh -c \"$*\"\n");
  fs::permissions(dir / "fake-ssh", fs::perms::owner_all);
  testing::write_text(dir / "h{=system(\"touch\",\"PWNED6\")=}", "1/node-a\n");
  const auto hosts = testing::run_study({"run", "c.json", "--results", "H", "--hosts", "h{=system(\"touch\",\"PWNED6\")=}",
                                         "--ssh", (dir / "fake-ssh").string()},
                                        dir);
  INFO(hosts.output);
  CHECK(hosts.exit_code == 0);
  CHECK(pwned_files(dir).empty());
  fs::remove_all(dir);
}

TEST_CASE("a member file held locked by another process is reported unreadable, never deleted or rerun",
          "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("locked_member");
  testing::write_text(dir / "c.json", testing::tiny_campaign("locked", {0.02, 0.03}, 0.3, 0).dump());
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  const MemberPaths p = s.layout.member(s.members[0]);
  const std::string before = testing::read_text(p.h5);
  {
    const HeldLock lock(p.h5);
    const auto run = testing::run_study({"run", "c.json"}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 3);
    CHECK(run.output.find("[unreadable] " + s.members[0].dir_name()) != std::string::npos);
    CHECK(run.output.find("another process holds it locked") != std::string::npos);
    CHECK(run.output.find("running 1 of") == std::string::npos);  // nothing was run over it
    const auto status = testing::run_study({"status", "c.json", "--json"}, dir);
    const auto j = nlohmann::json::parse(status.output);
    CHECK(j["counts"]["unreadable"] == 1);
    CHECK(j["counts"].contains("running"));
  }
  CHECK(testing::read_text(p.h5) == before);  // byte-identical
  CHECK(testing::run_study({"status", "c.json"}, dir).exit_code == 0);
  fs::remove_all(dir);
}

TEST_CASE("a member folder that cannot be looked into is unreadable, not new", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("unreadable_folder");
  testing::write_text(dir / "c.json", testing::tiny_campaign("folder", {0.02}, 0.3, 0).dump());
  const CampaignSurvey s0 = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  // A file where the members folder should be: every lookup below it fails with ENOTDIR (as
  // root, which passes every permission check, this is the failure a test can make).
  fs::create_directories(s0.layout.root);
  testing::write_text(s0.layout.members_dir(), "not a folder");
  const auto status = testing::run_study({"status", "c.json"}, dir);
  INFO(status.output);
  CHECK(status.exit_code == 3);
  CHECK(status.output.find("[unreadable]") != std::string::npos);
  CHECK(status.output.find("cannot look into the member folder") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a corrupt member file is refused by reuse and by report - the previous report stays", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("corrupt_member");
  testing::write_text(dir / "first.json", testing::tiny_campaign("first", {0.02, 0.03}, 0.3, 0).dump());
  testing::write_text(dir / "second.json", testing::tiny_campaign("second", {0.02}, 0.3, 0).dump());
  REQUIRE(testing::run_study({"run", "first.json"}, dir).exit_code == 0);
  REQUIRE(testing::run_study({"report", "first.json"}, dir).exit_code == 0);
  const CampaignSurvey s = survey_campaign((dir / "first.json").string(), dir / "results", slurm_queue);
  const MemberPaths p = s.layout.member(s.members[0]);
  const fs::path fits = s.layout.report_dir() / "fits.json";
  const std::string good_report = testing::read_text(fits);

  SECTION("one flipped bit in a series") { capsule::testing::flip_bit_in_dataset(p.h5.string(), "series/D_xy"); }
  SECTION("a deleted series") {
    const hid_t f = H5Fopen(p.h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(f, "series/D_xy", H5P_DEFAULT);
    H5Fclose(f);
  }
  // Reuse: the second campaign's member has the same id, but the source does not read whole.
  const auto second = testing::run_study({"run", "second.json"}, dir);
  INFO(second.output);
  CHECK(second.exit_code == 0);
  CHECK(second.output.find("not copied from first/members/" + s.members[0].dir_name()) != std::string::npos);
  CHECK(second.output.find("running 1 of 1") != std::string::npos);  // run, not copied

  // Report: refused, exit 3, the previous report byte-identical.
  const auto report = testing::run_study({"report", "first.json"}, dir);
  INFO(report.output);
  CHECK(report.exit_code == 3);
  CHECK(report.output.find("report not written") != std::string::npos);
  CHECK(testing::read_text(fits) == good_report);
  CHECK_FALSE(fs::exists(s.layout.report_dir() / "PARTIAL.md"));

  // --partial writes it without that member and says so.
  const auto partial = testing::run_study({"report", "first.json", "--partial"}, dir);
  INFO(partial.output);
  CHECK(partial.exit_code == 3);
  const std::string note = testing::read_text(s.layout.report_dir() / "PARTIAL.md");
  CHECK(note.find(s.members[0].dir_name()) != std::string::npos);
  CHECK(testing::read_text(fits) != good_report);
  for (const auto& e : fs::directory_iterator(s.layout.root))
    CHECK(e.path().filename().string().find("report.staging") == std::string::npos);  // nothing left behind
  fs::remove_all(dir);
}

TEST_CASE("GNU Parallel's own failure and an unreachable host are named, exit 1", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("parallel_failure");
  testing::write_text(dir / "c.json", testing::tiny_campaign("pfail", {0.01, 0.02, 0.03, 0.04}, 0.3, 0).dump());
  // ssh's exit status 255 for host "dead"; the other host runs the command here.
  testing::write_text(dir / "fake-ssh",
                      "#!/bin/sh\nhost=$1; shift\n[ \"$host\" = dead ] && { echo 'ssh: connect to host dead: refused' >&2; "
                      "exit 255; }\n[ \"$1\" = \"--\" ] && shift\nexec sh -c \"$*\"\n");
  fs::permissions(dir / "fake-ssh", fs::perms::owner_all);

  SECTION("a hosts line GNU Parallel cannot parse") {
    testing::write_text(dir / "hosts", "abc/node-a\n");
    const auto run = testing::run_study({"run", "c.json", "--hosts", "hosts", "--ssh", (dir / "fake-ssh").string()}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 1);
    CHECK(run.output.find("GNU Parallel itself failed (exit status 255") != std::string::npos);
  }
  SECTION("a host that refuses the connection, beside one that works: its members run on the other") {
    testing::write_text(dir / "hosts", "1/node-a\n1/dead\n");
    const auto run = testing::run_study({"run", "c.json", "--hosts", "hosts", "--ssh", (dir / "fake-ssh").string()}, dir);
    INFO(run.output);
    // GNU Parallel's joblog keeps a job's last try only, so a host whose members all ran
    // elsewhere on retry leaves no row to name it by; what counts is that nothing was lost.
    CHECK(run.exit_code == 0);
    CHECK(survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue).count(MemberState::complete) == 4);
  }
  SECTION("only a host that refuses the connection: exit 1, each member named") {
    testing::write_text(dir / "hosts", "1/dead\n");
    const auto run = testing::run_study({"run", "c.json", "--hosts", "hosts", "--ssh", (dir / "fake-ssh").string()}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 1);
    CHECK(run.output.find("host dead could not be reached (exit 255) for 4 members") != std::string::npos);
    CHECK(run.output.find("did not run: no host it was given could be reached") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("study export takes the run lock: during a run it exits 5 and writes no job list", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("export_lock");
  testing::write_text(dir / "c.json", testing::tiny_campaign("xlock", {0.02}, 0.3, 0).dump());
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  fs::create_directories(s.layout.root);
  const RunLock held(s.layout.lock_file(), s.layout.running_info(), {});  // as a `study run` holds it
  const auto exported = testing::run_study({"export", "c.json", "--slurm"}, dir);
  INFO(exported.output);
  CHECK(exported.exit_code == 5);
  CHECK(exported.output.find("another `study run` of this campaign is still going") != std::string::npos);
  CHECK_FALSE(fs::exists(s.layout.slurm_dir() / "jobs"));
  fs::remove_all(dir);
}

TEST_CASE("a file that cannot be written names errno's reason and leaves no temporary file", "[study][integrity]") {
  const fs::path dir = testing::scratch_dir("write_failure");
  // A path through a regular file: the temporary cannot be created (ENOTDIR), as a full or
  // read-only disk refuses it with ENOSPC or EROFS.
  testing::write_text(dir / "file", "x");
  try {
    write_file_atomically(dir / "file" / "run.json", "{}\n");
    FAIL("written through a file");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("Not a directory") != std::string::npos);
    CHECK(std::string(e.what()).find("run.json") != std::string::npos);
  }
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);
  fs::remove_all(dir);
}

TEST_CASE("a build whose sources differ from every commit is refused by run and export unless allowed", "[study][integrity]") {
  CHECK(is_uncommitted_version("dd96afe09c74-dirty-c0787bbcd4fe"));
  CHECK(is_uncommitted_version("unknown"));
  CHECK(is_uncommitted_version(""));
  CHECK_FALSE(is_uncommitted_version("dd96afe09c74"));
  CHECK_FALSE(is_uncommitted_version("v1.2-14-gdd96afe09c74"));
  CHECK_THROWS_AS(require_committed_build("abc-dirty-0123", false, "study run"), DirtyBuild);
  CHECK_NOTHROW(require_committed_build("abc-dirty-0123", true, "study run"));
  CHECK_NOTHROW(require_committed_build("abc", false, "study run"));
  try {
    require_committed_build("abc-dirty-0123", false, "study run");
  } catch (const DirtyBuild& e) {
    CHECK(std::string(e.what()).find("--allow-dirty") != std::string::npos);
  }
  // This build, through the binary, without the test suite's STUDY_ALLOW_DIRTY: a dirty build
  // refuses (exit 2, nothing written); a committed one runs.
  const fs::path dir = testing::scratch_dir("dirty_build");
  testing::write_text(dir / "c.json", testing::tiny_campaign("dirty", {0.02}, 0.3, 0).dump());
  const auto run = testing::run_shell("cd " + shell_quote(dir.string()) + " && env -u STUDY_ALLOW_DIRTY CAPSULE_BIN=" +
                                      shell_quote(testing::capsule_binary().string()) + " " +
                                      shell_quote(testing::study_binary().string()) + " run c.json </dev/null");
  INFO(run.output);
  if (is_uncommitted_version(capsule::build::code_version)) {
    CHECK(run.exit_code == 2);
    CHECK(run.output.find("this build's code version is") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "results"));
  } else {
    CHECK(run.exit_code == 0);
  }
  fs::remove_all(dir);
}
