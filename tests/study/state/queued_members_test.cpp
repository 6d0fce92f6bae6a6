// The survey marks the members its queue reader names as queued (study/state/campaign_survey.hpp):
// the reader is passed in (Slurm's in the binary), so the state room knows no batch system.
#include <catch2/catch.hpp>

#include "study/state/campaign_survey.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

TEST_CASE("the survey marks the members the queue reader names as queued, with its note", "[study]") {
  const fs::path dir = testing::scratch_dir("queued_members");
  testing::write_text(dir / "c.json", testing::tiny_campaign("queued", {0.05, 0.1}, 1, 1).dump(2));
  const CampaignSurvey plain = survey_campaign((dir / "c.json").string(), dir / "results",
                                               [](const ResultsLayout&) { return QueuedMembers{}; });
  REQUIRE(plain.members.size() == 2);
  CHECK(plain.count(MemberState::fresh) == 2);
  CHECK(plain.note.empty());

  const std::string waiting = plain.members[1].dir_name();
  fs::path asked;
  const CampaignSurvey s = survey_campaign((dir / "c.json").string(), dir / "results", [&](const ResultsLayout& layout) {
    asked = layout.members_dir();
    return QueuedMembers{{{waiting, "job queued task 1 (PENDING)"}}, "one queue of two not asked"};
  });
  CHECK(asked == plain.layout.members_dir());
  CHECK(s.conditions[0].state == MemberState::fresh);
  CHECK(s.conditions[1].state == MemberState::queued);
  CHECK(s.conditions[1].reason == "waiting in Slurm's queue: job queued task 1 (PENDING)");
  CHECK(s.note == "one queue of two not asked");
}
