// What a kill (-9) leaves behind is cleaned by the next run or report, never piles up and is
// never read as the member's state: a restart point, progress file and temporaries beside a
// member that completed, and the staging folder of a killed report.
#include <catch2/catch.hpp>

#include <unistd.h>

#include "study/state/results_layout.hpp"
#include "study/state/run_record.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// The one member folder of a campaign's results.
fs::path only_member(const fs::path& results_campaign) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(results_campaign / "members")) found.push_back(e.path());
  REQUIRE(found.size() == 1);
  return found.front();
}

}  // namespace

TEST_CASE("leftovers of a killed attempt beside a complete member are removed by the next run", "[study]") {
  const fs::path dir = testing::scratch_dir("leftovers_member");
  testing::write_text(dir / "c.json", testing::tiny_campaign("left", {0.05}, 0.3, 0.2).dump(2));
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const fs::path member = only_member(dir / "results" / "left");
  const MemberPaths p = member_paths_in(member);
  // A kill after the final rename, and temporaries of killed writers (pids long gone).
  for (const auto& f : {p.restart, p.progress, p.partial, fs::path(p.restart.string() + ".tmp.4194000"),
                        fs::path(p.progress.string() + ".tmp.4194001")})
    testing::write_text(f, "left by a kill");
  const auto again = testing::run_study({"run", "c.json"}, dir);
  INFO(again.output);
  CHECK(again.exit_code == 0);
  CHECK_THAT(again.output, Catch::Contains("complete: 1"));
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(member)) left.push_back(e.path().filename().string());
  INFO(testing::read_text(member / "capsule.log"));
  for (const auto& name : left) {
    INFO(name);
    CHECK(name.find(".restart") == std::string::npos);
    CHECK(name.find(".progress") == std::string::npos);
    CHECK(name.find(".partial") == std::string::npos);
    CHECK(name.find(".tmp") == std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("a killed report's staging folder is removed by the next report", "[study]") {
  const fs::path dir = testing::scratch_dir("leftovers_report");
  testing::write_text(dir / "c.json", testing::tiny_campaign("stage", {0.05}, 0.3, 0.2).dump(2));
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  const fs::path campaign = dir / "results" / "stage";
  // One of a report killed on this host (its pid no longer runs), one of another host a day
  // old, one of another host that may still be writing (kept).
  const fs::path killed_here = campaign / ("report.staging." + host_name() + ".4194002");
  const fs::path old_elsewhere = campaign / "report.staging.other-host.12";
  const fs::path fresh_elsewhere = campaign / "report.staging.other-host.13";
  for (const auto& d : {killed_here, old_elsewhere, fresh_elsewhere}) {
    fs::create_directories(d);
    testing::write_text(d / "fits.json", "{}");
  }
  testing::set_age(old_elsewhere, 2 * 24 * 3600.0);
  const auto r = testing::run_study({"report", "c.json"}, dir);
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK_FALSE(fs::exists(killed_here));
  CHECK_FALSE(fs::exists(old_elsewhere));
  CHECK(fs::exists(fresh_elsewhere));
  for (const auto& e : fs::directory_iterator(campaign)) {
    const std::string n = e.path().filename().string();
    if (e.path() != fresh_elsewhere) CHECK(n.find("staging") == std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("thesis warns of a report older than its member files, or a fits.json edited after the report", "[study]") {
  const fs::path dir = testing::scratch_dir("thesis_inputs");
  testing::write_text(dir / "c.json", testing::tiny_campaign("fresh", {0.05}, 0.3, 0.2).dump(2));
  REQUIRE(testing::run_study({"run", "c.json"}, dir).exit_code == 0);
  REQUIRE(testing::run_study({"report", "c.json"}, dir).exit_code == 0);
  const fs::path fits = dir / "results" / "fresh" / "report" / "fits.json";
  REQUIRE(fs::exists(fits));
  const std::vector<std::string> thesis{"thesis", "--results", "results", "-o", "T.md"};
  {
    const auto r = testing::run_study(thesis, dir);
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("warning: campaign fresh") == std::string::npos);  // a current report: nothing said
  }
  SECTION("a member file newer than the report") {
    const fs::path h5 = only_member(dir / "results" / "fresh") / "member.h5";
    fs::last_write_time(h5, fs::last_write_time(fits) + std::chrono::seconds(5));
    const auto r = testing::run_study(thesis, dir);
    INFO(r.output);
    CHECK_THAT(r.output, Catch::Contains("warning: campaign fresh: 1 member file is newer than its report") &&
                             Catch::Contains(h5.filename().string()) &&
                             Catch::Contains("run `study report c.json` again before `study thesis`"));
  }
  SECTION("fits.json edited") {
    std::string text = testing::read_text(fits);
    text.insert(text.find('{') + 1, "\"edited\": true, ");
    testing::write_text(fits, text);
    fs::last_write_time(fits, fs::last_write_time(fits) - std::chrono::seconds(0));
    const auto r = testing::run_study(thesis, dir);
    INFO(r.output);
    CHECK_THAT(r.output, Catch::Contains("warning: campaign fresh:") &&
                             Catch::Contains("fits.json was changed after `study report` wrote it") &&
                             Catch::Contains("run `study report c.json` again"));
  }
  fs::remove_all(dir);
}

TEST_CASE("thesis that cannot write its file gives the OS reason", "[study]") {
  const fs::path dir = testing::scratch_dir("thesis_cannot_write");
  fs::create_directories(dir / "results");
  fs::create_directories(dir / "T.md");  // a folder where the file should go
  const auto r = testing::run_study({"thesis", "--results", "results", "-o", "T.md"}, dir);
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("cannot write T.md (renaming T.md.tmp.") && Catch::Contains("): Is a directory"));
  CHECK(fs::is_directory(dir / "T.md"));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
  fs::remove_all(dir);
}
