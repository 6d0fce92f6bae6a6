// Folders without permission, as an unprivileged user meets them (the suite runs as root, for
// whom no permission bit refuses anything, so the commands run as nobody through setpriv; the
// test says why it skips where the machine refuses that): a member folder that cannot be read
// is named with the OS reason by `report --partial` (which goes on without it) and by `run`
// (which runs the others); a results folder or member file that cannot be written is named.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <iostream>

#include "study/run/shell_quote.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

constexpr const char* kNobody = "65534";

std::string as_nobody(const fs::path& cwd, const std::string& program, const std::vector<std::string>& args) {
  std::string line = "cd ";
  line.append(shell_quote(cwd.string()))
      .append(" && HOME=")
      .append(shell_quote(cwd.string()))
      .append(" CAPSULE_BIN=")
      .append(shell_quote(testing::capsule_binary().string()))
      .append(" setpriv --reuid=")
      .append(kNobody)
      .append(" --regid=")
      .append(kNobody)
      .append(" --clear-groups ")
      .append(shell_quote(program));
  for (const auto& a : args) line.append(" ").append(shell_quote(a));
  return line.append(" </dev/null");
}

// Why commands cannot run as nobody here ("" when they can): not root, no setpriv, or the
// binaries out of nobody's reach.
std::string cannot_run_as_nobody(const fs::path& dir) {
  if (::geteuid() != 0) return "the tests do not run as root (the permission bits refuse the user itself)";
  const auto r = testing::run_shell(as_nobody(dir, "test", {"-x", testing::study_binary().string(), "-a", "-x",
                                                             testing::capsule_binary().string()}));
  if (r.exit_code != 0) return "setpriv cannot run the binaries as nobody here: " + r.output;
  return "";
}

// Opens dir to everyone's reading; when commands cannot run as nobody here, says why, removes
// dir and returns true (the test is skipped).
bool skipped_unless_nobody_can_run(const fs::path& dir) {
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                           fs::perms::others_exec);
  const std::string why = cannot_run_as_nobody(dir);
  if (why.empty()) return false;
  std::cout << "skipped (" << why << ")\n";
  WARN("skipped: " << why);
  fs::remove_all(dir);
  return true;
}

void give_to_nobody(const fs::path& dir) {
  REQUIRE(testing::run_shell("chown -R " + std::string(kNobody) + ":" + kNobody + " " + shell_quote(dir.string())).exit_code == 0);
}

}  // namespace

TEST_CASE("a member folder nobody may read: report --partial goes on without it, run names it", "[study]") {
  const fs::path dir = testing::scratch_dir("unprivileged_member");
  if (skipped_unless_nobody_can_run(dir)) return;
  testing::write_text(dir / "c.json", testing::tiny_campaign("locked", {0.04, 0.05}, 0.3, 0.2).dump(2));
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  give_to_nobody(dir);
  fs::path closed;
  for (const auto& e : fs::directory_iterator(dir / "results" / "locked" / "members")) closed = e.path();
  fs::permissions(closed, fs::perms::none);
  const std::string study = testing::study_binary().string();

  const auto report = testing::run_shell(as_nobody(dir, study, {"report", "c.json", "--partial"}));
  INFO(report.output);
  CHECK(report.exit_code == 3);  // written, without one member
  CHECK_THAT(report.output, Catch::Contains("cannot read " + closed.filename().string()) &&
                                Catch::Contains(closed.string()) && Catch::Contains("Permission denied"));
  CHECK(fs::exists(dir / "results" / "locked" / "report" / "PARTIAL.md"));

  const auto run = testing::run_shell(as_nobody(dir, study, {"run", "c.json"}));
  INFO(run.output);
  CHECK(run.exit_code == 3);  // one member unreadable, the other complete
  CHECK_THAT(run.output, Catch::Contains(closed.filename().string()) && Catch::Contains("Permission denied"));
  CHECK_THAT(run.output, Catch::Contains("complete: 1"));

  fs::permissions(closed, fs::perms::owner_all);
  fs::remove_all(dir);
}

TEST_CASE("a results folder nobody may write: run names it and the OS reason", "[study]") {
  const fs::path dir = testing::scratch_dir("unprivileged_results");
  if (skipped_unless_nobody_can_run(dir)) return;
  testing::write_text(dir / "c.json", testing::tiny_campaign("closed", {0.05}, 0.3, 0.2).dump(2));
  fs::create_directories(dir / "results");  // root's, read-only to nobody
  const auto run = testing::run_shell(as_nobody(dir, testing::study_binary().string(), {"run", "c.json"}));
  INFO(run.output);
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.output, Catch::Contains((dir / "results").string()) && Catch::Contains("Permission denied"));
  CHECK_FALSE(fs::exists(dir / "results" / "closed"));

  // capsule itself: a member file it may not create.
  testing::write_text(dir / "s.json", testing::tiny_scene(0.1, 0.1).dump(2));
  const auto capsule = testing::run_shell(
      as_nobody(dir, testing::capsule_binary().string(), {"s.json", "-o", (dir / "results" / "m.h5").string()}));
  INFO(capsule.output);
  CHECK(capsule.exit_code != 0);
  CHECK_THAT(capsule.output, Catch::Contains((dir / "results").string()) && Catch::Contains("Permission denied"));
  fs::remove_all(dir);
}
