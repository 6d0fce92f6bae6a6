// The results shipped under results/<campaign>/ still belong to their campaign files: a change
// of the physics version (or of a campaign's parameters) changes member ids, so shipped member
// files would no longer be found and `study run` would rerun them. This test notices that.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "solver/io/member_file.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"
#include "solver/scene/version.hpp"
#include "study/run/provenance.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

bool final_state(MemberState s) {
  return s == MemberState::complete || s == MemberState::unstable || s == MemberState::stopped;
}

// The campaigns whose base still names an earlier physics version, waiting for their rerun on
// today's (docs/guide/campaigns.md "Physics versions"). Exactly the pinned ones: a campaign moved
// to today's physics leaves this list, and a new pin has to be written here.
const std::set<std::string> awaiting_rerun = {};

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
    const CampaignSurvey s = survey_campaign(entry.path().string(), results, slurm_queue);
    // Provenance: a campaign on today's physics ships only members of today's physics made by a
    // committed build (a `-dirty` code_version cannot be reproduced from any commit).
    const std::string pinned = s.campaign.base.value("physics_version", std::string());
    const bool current = pinned.empty() || pinned == capsule::physics_version;
    CHECK(current != (awaiting_rerun.count(s.campaign.name) == 1));
    for (std::size_t i = 0; current && i < s.members.size(); ++i) {
      if (!final_state(s.conditions[i].state)) continue;
      const auto status = capsule::io::read_member_status(s.layout.member(s.members[i]).h5.string());
      INFO(s.members[i].dir_name() << ": code " << status.code_version << ", physics " << status.physics_version);
      CHECK_FALSE(is_uncommitted_version(status.code_version));
      CHECK(status.physics_version == capsule::physics_version);
      // And the relaxation time that today's rule chooses for it (a member whose scene leaves tau
      // to the rule, run before the rule changed within a physics version, must be rerun).
      const capsule::Scene scene = capsule::Scene::from_json(s.members[i].scene, s.members[i].dir_name());
      if (scene.resolution.tau == 0 && status.status == "complete") CHECK(status.tau == Approx(capsule::choose_tau(scene)).epsilon(1e-12));
    }
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
        // The report lists every member that has a file (a report written before today's
        // reporting may leave out the members not yet run; today's lists them as missing).
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

TEST_CASE("shipped results: the campaigns awaiting a rerun on today's physics are exactly the pinned ones", "[study]") {
  // Also for a campaign with nothing shipped yet, so the list cannot name a campaign that is gone.
  std::set<std::string> pinned;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(CAPSULE_SOURCE_DIR) / "campaigns")) {
    if (entry.path().extension() != ".json") continue;
    const Campaign c = load_campaign(entry.path().string());
    const std::string v = c.base.value("physics_version", std::string());
    if (!v.empty() && v != capsule::physics_version) pinned.insert(c.name);
  }
  CHECK(pinned == awaiting_rerun);
}
