// The results shipped under results/<campaign>/ still belong to their campaign files: a change
// of the physics version (or of a campaign's parameters) changes member ids, so shipped member
// files would no longer be found and `study run` would rerun them. This test notices that.
#include <catch2/catch.hpp>

#include <set>

#include "study/campaign_survey.hpp"
#include "tests/study/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

bool final_state(MemberState s) {
  return s == MemberState::complete || s == MemberState::unstable || s == MemberState::stopped;
}

}  // namespace

TEST_CASE("shipped results match their campaigns: no orphaned member, a shipped report is complete", "[study]") {
  const fs::path source(CAPSULE_SOURCE_DIR);
  const fs::path results = source / "results";
  std::size_t shipped = 0;
  for (const auto& entry : fs::directory_iterator(source / "campaigns")) {
    if (entry.path().extension() != ".json") continue;
    const fs::path root = results / entry.path().stem();
    if (!fs::exists(root / "members")) continue;
    ++shipped;
    INFO(entry.path().string());
    const CampaignSurvey s = survey_campaign(entry.path().string(), results);
    std::set<std::string> known;
    for (const auto& m : s.members) known.insert(m.dir_name());
    // Every member file that is there belongs to a member of today's campaign.
    for (const auto& dir : fs::directory_iterator(root / "members")) {
      if (!fs::exists(dir.path() / "member.h5")) continue;
      INFO("member folder " << dir.path().filename().string());
      CHECK(known.count(dir.path().filename().string()) == 1);
    }
    // A campaign whose report is shipped has every member in a final state: complete, or
    // unstable / stopped (results too, reported with their reason).
    if (fs::exists(root / "report" / "fits.json"))
      for (std::size_t i = 0; i < s.members.size(); ++i) {
        INFO(s.members[i].dir_name() << ": " << s.conditions[i].reason);
        CHECK(final_state(s.conditions[i].state));
      }
  }
  INFO("shipped campaigns checked: " << shipped);
  SUCCEED();
}
