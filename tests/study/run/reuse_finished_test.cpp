// A member that another campaign under the same results folder finished (same member id: same
// canonical scene and physics version) is copied by `study run`, not run again, and `study plan`
// leaves it out of the cost (member_reuse.hpp). An unfinished one is not copied, and
// --no-reuse runs every member.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "study/run/joblog.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

const Member& member_with_ca(const CampaignSurvey& s, double ca) {
  for (const auto& m : s.members)
    if (m.scene.at("Ca").get<double>() == ca) return m;
  throw std::runtime_error("no member with that Ca");
}

}  // namespace

TEST_CASE("study run copies a member another campaign finished instead of running it", "[study]") {
  const fs::path dir = testing::scratch_dir("reuse_finished");
  testing::write_text(dir / "first.json", testing::tiny_campaign("first", {0.01, 0.02}, 0.5, 0).dump(2));
  testing::write_text(dir / "second.json", testing::tiny_campaign("second", {0.02, 0.03}, 0.5, 0).dump(2));
  const auto first = testing::run_study({"run", "first.json", "-j", "1"}, dir);
  INFO(first.output);
  REQUIRE(first.exit_code == 0);
  const CampaignSurvey a = survey_campaign((dir / "first.json").string(), dir / "results", slurm_queue);

  SECTION("plan names the copy and leaves it out of the cost; run copies it and runs only the other") {
    const auto plan = testing::run_study({"plan", "second.json"}, dir);
    INFO(plan.output);
    CHECK(plan.exit_code == 0);
    CHECK_THAT(plan.output, Catch::Contains("finished in first: `study run` copies it") &&
                                Catch::Contains("1 of them finished in other campaigns") &&
                                Catch::Contains("for 1 members"));

    const auto run = testing::run_study({"run", "second.json", "-j", "1"}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("copied " + member_with_ca(a, 0.02).dir_name() + " from first"));
    const CampaignSurvey b = survey_campaign((dir / "second.json").string(), dir / "results", slurm_queue);
    CHECK(b.count(MemberState::complete) == 2);
    CHECK(read_joblog(b.layout.joblog()).size() == 1);  // only Ca 0.03 ran
    const MemberPaths copy = b.layout.member(member_with_ca(b, 0.02));
    CHECK(testing::read_text(copy.h5) == testing::read_text(a.layout.member(member_with_ca(a, 0.02)).h5));
    CHECK_THAT(testing::read_text(copy.log), Catch::Contains("study: copied from first/members/"));
    for (const auto& entry : fs::directory_iterator(copy.dir))  // the copy's temporary renamed away
      CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);
  }

  SECTION("study export --slurm copies it and leaves it out of the array; --no-reuse exports it") {
    const auto all = testing::run_study({"export", "second.json", "--slurm", "--no-reuse"}, dir);
    INFO(all.output);
    CHECK(all.exit_code == 0);
    CHECK_THAT(all.output, !Catch::Contains("copied ") && Catch::Contains("2 of 2 members to run"));
    const auto exported = testing::run_study({"export", "second.json", "--slurm"}, dir);
    INFO(exported.output);
    CHECK(exported.exit_code == 0);
    CHECK_THAT(exported.output, Catch::Contains("copied " + member_with_ca(a, 0.02).dir_name() + " from first") &&
                                    Catch::Contains("1 of 2 members to run"));
    const CampaignSurvey b = survey_campaign((dir / "second.json").string(), dir / "results", slurm_queue);
    CHECK(b.count(MemberState::complete) == 1);
  }

  SECTION("--no-reuse runs the member although another campaign finished it") {
    const auto run = testing::run_study({"run", "second.json", "-j", "1", "--no-reuse"}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, !Catch::Contains("copied "));
    const CampaignSurvey b = survey_campaign((dir / "second.json").string(), dir / "results", slurm_queue);
    CHECK(read_joblog(b.layout.joblog()).size() == 2);
  }

  SECTION("a member that did not finish there is run here") {
    // The first campaign's Ca 0.02 member loses its member file: interrupted or failed there.
    fs::remove(a.layout.member(member_with_ca(a, 0.02)).h5);
    const auto plan = testing::run_study({"plan", "second.json"}, dir);
    INFO(plan.output);
    CHECK_THAT(plan.output, !Catch::Contains("finished in first") && Catch::Contains("for 2 members"));
    const auto run = testing::run_study({"run", "second.json", "-j", "1"}, dir);
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, !Catch::Contains("copied "));
    const CampaignSurvey b = survey_campaign((dir / "second.json").string(), dir / "results", slurm_queue);
    CHECK(read_joblog(b.layout.joblog()).size() == 2);
  }
  fs::remove_all(dir);
}
