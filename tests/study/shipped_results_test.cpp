// The results shipped under results/<campaign>/ still belong to their campaign files: a change
// of the physics version (or of a campaign's parameters) changes member ids, so shipped member
// files would no longer be found and `study run` would rerun them. This test notices that.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "study/state/campaign_survey.hpp"
#include "tests/study/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

bool final_state(MemberState s) {
  return s == MemberState::complete || s == MemberState::unstable || s == MemberState::stopped;
}

}  // namespace

TEST_CASE("shipped results match their campaigns: no orphaned member or stale folder, a shipped report agrees with the member files", "[study]") {
  const fs::path source(CAPSULE_SOURCE_DIR);
  const fs::path results = source / "results";
  std::size_t shipped = 0;
  for (const auto& entry : fs::recursive_directory_iterator(source / "campaigns")) {
    if (entry.path().extension() != ".json") continue;
    const fs::path root = results / entry.path().stem();
    if (!fs::exists(root / "members")) continue;
    ++shipped;
    INFO(entry.path().string());
    const CampaignSurvey s = survey_campaign(entry.path().string(), results);
    std::set<std::string> known;
    for (const auto& m : s.members) known.insert(m.dir_name());
    // Every member folder that is there belongs to a member of today's campaign (a stale one,
    // even holding only its scene, is not shipped: `study plan` names such folders).
    for (const auto& dir : fs::directory_iterator(root / "members")) {
      INFO("member folder " << dir.path().filename().string());
      CHECK(known.count(dir.path().filename().string()) == 1);
    }
    // A shipped report agrees with the shipped member files: every member it lists belongs to
    // today's campaign, every member with a final file is listed, and a member is "complete"
    // in the report exactly when its file is. A report may ship before every member has run
    // (the 2D case of a 2D/3D campaign, say).
    const fs::path fits = root / "report" / "fits.json";
    if (fs::exists(fits)) {
      std::ifstream in(fits);
      const nlohmann::json j = nlohmann::json::parse(in);
      std::map<std::string, std::string> reported;  // id -> status
      for (const auto& m : j.at("members")) reported[m.at("id").get<std::string>()] = m.at("status").get<std::string>();
      std::set<std::string> ids;
      for (std::size_t i = 0; i < s.members.size(); ++i) {
        ids.insert(s.members[i].id);
        INFO(s.members[i].dir_name() << ": " << s.conditions[i].reason);
        const auto it = reported.find(s.members[i].id);
        // The report lists every member that has a file (study report leaves out, and counts,
        // the members not yet run).
        if (it == reported.end()) {
          CHECK_FALSE(final_state(s.conditions[i].state));
          continue;
        }
        CHECK((it->second == "complete") == (s.conditions[i].state == MemberState::complete));
        if (final_state(s.conditions[i].state) && s.conditions[i].state != MemberState::complete)
          CHECK(it->second.rfind(s.conditions[i].state == MemberState::unstable ? "unstable" : "stopped", 0) == 0);
      }
      for (const auto& [id, status] : reported) {
        INFO("reported member " << id);
        CHECK(ids.count(id) == 1);
      }
    }
  }
  INFO("shipped campaigns checked: " << shipped);
  SUCCEED();
}
