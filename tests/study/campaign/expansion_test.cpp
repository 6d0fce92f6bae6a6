// Campaign expansion: sweep counts, case overrides, and member ids (canonical hashing).
#include <catch2/catch.hpp>

#include "solver/scene/version.hpp"
#include <filesystem>
#include <set>

#include "study/campaign/campaign.hpp"
#include "study/campaign/expansion.hpp"
#include "study/campaign/member_id.hpp"
#include "solver/io/member_file.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
using nlohmann::json;

namespace {
std::vector<Member> expand_text(const json& doc) { return expand_campaign(parse_campaign(doc.dump(), "test.json")); }
}  // namespace

TEST_CASE("FNV-1a 64 matches the published test vectors", "[study]") {
  // Vectors from the FNV reference (Fowler/Noll/Vo, draft-eastlake-fnv): "" and "a".
  CHECK(fnv1a_64("") == 0xcbf29ce484222325ull);
  CHECK(fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a_64("foobar") == 0x85944171f73967e8ull);
}

TEST_CASE("a grid sweep is the Cartesian product, a zip sweep advances together", "[study]") {
  json doc = testing::tiny_campaign("grid", {0.01, 0.02, 0.03}, 1, 1);
  doc["sweep"]["grid"]["E_b"] = {0.0, 0.05};
  auto members = expand_text(doc);
  REQUIRE(members.size() == 6);
  std::set<std::pair<double, double>> seen;
  for (const auto& m : members) seen.emplace(m.scene["Ca"].get<double>(), m.scene["E_b"].get<double>());
  CHECK(seen.size() == 6);
  CHECK(seen.count({0.02, 0.05}) == 1);

  json zipped = testing::tiny_campaign("zip", {0.01}, 1, 1);
  zipped["sweep"] = {{"zip", {{"Ca", {0.01, 0.02, 0.03}}, {"resolution.a", {4, 5, 6}}}}};
  members = expand_text(zipped);
  REQUIRE(members.size() == 3);
  CHECK(members[1].scene["Ca"].get<double>() == 0.02);
  CHECK(members[1].scene["resolution"]["a"].get<double>() == 5.0);
  CHECK(members[1].scene["resolution"]["segments"].get<int>() == 32);  // the rest of "resolution" is kept

  zipped["sweep"]["grid"] = {{"E_b", {0.0, 0.1}}};  // zip rows x grid points
  CHECK(expand_text(zipped).size() == 6);
}

TEST_CASE("cases override keys and may bring their own sweep", "[study]") {
  json doc = testing::tiny_campaign("cases", {0.01, 0.02}, 1, 1);
  doc["cases"] = json::array({
      {{"name", "flat"}, {"set", {{"E_b", 0.0}}}},
      {{"name", "stiff"}, {"set", {{"E_b", 0.1}, {"protocol.shear.kt", 2.0}}}},
      {{"name", "own"}, {"set", {{"resolution", {{"a", 5}}}}}, {"sweep", {{"grid", {{"V", {1, 2, 5}}}}}}},
  });
  const auto members = expand_text(doc);
  REQUIRE(members.size() == 2 + 2 + 3);
  CHECK(members[0].case_name == "flat");
  CHECK(members[2].case_name == "stiff");
  CHECK(members[2].scene["E_b"].get<double>() == 0.1);
  CHECK(members[2].scene["protocol"]["shear"]["kt"].get<double>() == 2.0);
  CHECK(members[2].scene["protocol"]["shear"]["until"] == "time");  // merged, not replaced
  CHECK(members[4].case_name == "own");
  CHECK(members[4].scene["V"].get<double>() == 1.0);
  CHECK(members[6].scene["V"].get<double>() == 5.0);
  CHECK(members[6].scene["Ca"].get<double>() == 0.05);  // the case's own sweep replaced the Ca grid
  CHECK(members[6].scene["resolution"]["a"].get<double>() == 5.0);
  CHECK(members[6].slug == "own-V5");
  for (std::size_t i = 0; i < members.size(); ++i) CHECK(members[i].index == i);
}

TEST_CASE("member ids hash the canonical scene: spelling does not matter, parameters do", "[study]") {
  const json doc = testing::tiny_campaign("hash", {0.1}, 1, 1);
  const std::string id = expand_text(doc).at(0).id;
  CHECK(id.size() == 16);
  CHECK(id.find_first_not_of("0123456789abcdef") == std::string::npos);

  // Same scene, keys in another order and numbers spelled differently (0.1 vs 1e-1, 4 vs 4.0),
  // defaults written out.
  const std::string respelled = R"({"sweep": {"grid": {"Ca": [1e-1]}}, "name": "hash",
    "base": {"output": {"interval_kt": 1.0e-1}, "protocol": {"recover": {"kt": 1.0, "until": "time"},
             "shear": {"kt": 1, "until": "time"}}, "resolution": {"segments": 32, "a": 4.0},
             "eta": 0, "V": 1.0, "E_b": 0.0, "Ca": 5e-2, "shape": "circle", "dim": 2, "Re": 0.05}})";
  CHECK(expand_campaign(parse_campaign(respelled, "respelled.json")).at(0).id == id);

  // Any parameter change gives a new id.
  for (const auto& [key, value] : std::vector<std::pair<std::string, json>>{
           {"E_b", 0.001}, {"V", 2.0}, {"Re", 0.1}, {"eta", 1.0}}) {
    json changed = doc;
    changed["base"][key] = value;
    INFO(key);
    CHECK(expand_text(changed).at(0).id != id);
  }
  // A key the 2D model does not read (c0, mesh_level: 3D only) leaves a 2D id alone; in 3D it matters.
  json spontaneous = doc;
  spontaneous["base"]["c0"] = 0.5;
  spontaneous["base"]["resolution"]["mesh_level"] = 5;
  CHECK(expand_text(spontaneous).at(0).id == id);
  json three = doc;
  three["base"]["dim"] = 3;
  three["base"]["shape"] = "sphere";
  three["base"]["resolution"] = {{"a", 4}};
  const std::string id_3d = expand_text(three).at(0).id;
  three["base"]["c0"] = 0.5;
  CHECK(expand_text(three).at(0).id != id_3d);
  json finer = doc;
  finer["base"]["resolution"]["a"] = 5;
  CHECK(expand_text(finer).at(0).id != id);
  json longer = doc;
  longer["base"]["protocol"]["recover"]["kt"] = 1.5;
  CHECK(expand_text(longer).at(0).id != id);
  json other_ca = doc;
  other_ca["sweep"]["grid"]["Ca"] = {0.1000001};
  CHECK(expand_text(other_ca).at(0).id != id);
}

TEST_CASE("the physics version is part of the id", "[study]") {
  const json scene = expand_text(testing::tiny_campaign("v", {0.1}, 1, 1)).at(0).scene;
  CHECK(member_id(scene, "1") != member_id(scene, "2"));
  CHECK(member_id(scene, "1") == member_id(json::parse(scene.dump()), "1"));
  // The canonical scene names its version; the id hashes the scene without it, then the version.
  CHECK(scene.at("physics_version") == capsule::physics_version);
  CHECK(member_id(scene) == member_id(scene, capsule::physics_version));
  json without = scene;
  without.erase("physics_version");
  CHECK(member_id(scene, "5") == member_id(without, "5"));
}

TEST_CASE("a campaign that names physics version 5 keeps version 5's canonical text and ids", "[study]") {
  json doc = testing::tiny_campaign("v", {0.1}, 1, 1);
  const Member today = expand_text(doc).at(0);
  doc["base"]["physics_version"] = "5";
  const Member old = expand_text(doc).at(0);
  CHECK(old.id != today.id);
  CHECK(old.scene.at("physics_version") == "5");
  // The id version 5 gave: its canonical text (no physics_version key) and "5".
  json text5 = old.scene;
  text5.erase("physics_version");
  CHECK(old.id == member_id(text5, "5"));
  CHECK_FALSE(text5["resolution"].contains("collision"));  // left out at version 5's default
}

TEST_CASE("slugs are readable and safe as a path component", "[study]") {
  CHECK(member_slug("A", {{"Ca", json(0.05)}, {"resolution.a", json(8)}}) == "A-Ca0.05-a8");
  CHECK(member_slug("", {{"shape", json("bi/concave")}}) == "shapebi_concave");
  CHECK(member_slug("", {}) == "member");
  CHECK(member_slug(std::string(200, 'x'), {}).size() == 80);
}

TEST_CASE("one scene twice in a case is refused - shared by cases it is one member", "[study]") {
  json doc = testing::tiny_campaign("dup", {0.1, 1e-1}, 1, 1);
  CHECK_THROWS_WITH(expand_text(doc), Catch::Contains("same scene"));

  // One-at-a-time sweeps through a common base point (Ca = 0.05, E_b = 0).
  json shared = testing::tiny_campaign("shared", {0.05}, 1, 1);
  shared.erase("sweep");
  shared["cases"] = json::array({{{"name", "Ca"}, {"sweep", {{"grid", {{"Ca", {0.02, 0.05}}}}}}},
                                 {{"name", "E_b"}, {"sweep", {{"grid", {{"E_b", {0.0, 0.01}}}}}}}});
  const auto members = expand_text(shared);
  REQUIRE(members.size() == 3);
  CHECK(members[1].case_name == "Ca");
  CHECK(members[1].other_cases == std::vector<std::string>{"E_b"});
  CHECK(members[2].case_name == "E_b");
  CHECK(members[2].scene["E_b"].get<double>() == 0.01);
}

TEST_CASE("output-only keys leave the member id alone - the output interval does not", "[study]") {
  const json doc = testing::tiny_campaign("out", {0.1}, 1, 1);
  const Member plain = expand_text(doc).at(0);
  json shapes = doc;
  shapes["base"]["output"]["shapes_at_kt"] = {0.5, 1.0};
  const Member with_shapes = expand_text(shapes).at(0);
  CHECK(with_shapes.id == plain.id);
  CHECK(with_shapes.scene["output"]["shapes_at_kt"] == json({0.5, 1.0}));  // still written, and run
  json three = doc;
  three["base"]["dim"] = 3;
  three["base"]["shape"] = "sphere";
  three["base"]["resolution"] = {{"a", 4}};
  const std::string id_3d = expand_text(three).at(0).id;
  three["base"]["output"]["snapshots"] = "vtk";
  three["base"]["output"]["shapes_at_kt"] = {1.0};
  CHECK(expand_text(three).at(0).id == id_3d);
  // The stop tests read the rows the interval spaces: another interval is another run.
  json coarser = doc;
  coarser["base"]["output"]["interval_kt"] = 0.2;
  CHECK(expand_text(coarser).at(0).id != plain.id);
}

TEST_CASE("every shipped member's id is the hash of its scene.json and names its folder and member file", "[study]") {
  const std::filesystem::path results = std::filesystem::path(CAPSULE_SOURCE_DIR) / "results";
  std::size_t members = 0, files = 0;
  for (const auto& campaign : std::filesystem::directory_iterator(results)) {
    if (!std::filesystem::is_directory(campaign.path() / "members")) continue;
    for (const auto& member : std::filesystem::directory_iterator(campaign.path() / "members")) {
      const auto scene_path = member.path() / "scene.json";
      if (!std::filesystem::exists(scene_path)) continue;
      INFO(scene_path.string());
      const json scene = json::parse(testing::read_text(scene_path));
      const std::string folder = member.path().filename().string();
      const std::string id = member_id(scene);
      CHECK(folder.substr(folder.size() - 16) == id);
      ++members;
      if (const auto h5 = member.path() / "member.h5"; std::filesystem::exists(h5)) {
        CHECK(capsule::io::read_member_status(h5.string()).member_id == id);
        ++files;
      }
    }
  }
  CHECK(members >= 500);
  CHECK(files >= 500);
}
