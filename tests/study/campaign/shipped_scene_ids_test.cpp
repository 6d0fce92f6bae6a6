// Every shipped member's scene (results/<campaign>/members/<dir>/scene.json) parses and
// re-canonicalises byte for byte, and hashes to the id its folder is named with: the scene's
// parser and canonical text (solver/scene/scene.cpp) may be rewritten, never so that a shipped
// member's id or scene moves.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "solver/scene/scene.hpp"
#include "study/campaign/member_id.hpp"

namespace fs = std::filesystem;

TEST_CASE("every shipped member's scene re-canonicalises byte for byte to the id its folder names", "[study]") {
  const fs::path results = fs::path(CAPSULE_SOURCE_DIR) / "results";
  std::size_t checked = 0;
  for (const auto& campaign : fs::directory_iterator(results)) {
    const fs::path members = campaign.path() / "members";
    if (!fs::is_directory(members)) continue;
    for (const auto& member : fs::directory_iterator(members)) {
      const fs::path file = member.path() / "scene.json";
      if (!fs::exists(file)) continue;
      const std::string dir = member.path().filename().string();
      INFO(campaign.path().filename().string() << "/" << dir);
      std::ifstream in(file, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      const nlohmann::json shipped = nlohmann::json::parse(text.str());
      const nlohmann::json canonical = capsule::Scene::from_json(shipped, file.string()).to_json();
      CHECK(canonical.dump() == shipped.dump());
      const std::string id = capsule::study::member_id(canonical);
      CHECK(dir.size() > id.size());
      CHECK(dir.substr(dir.size() - id.size()) == id);
      CHECK(capsule::study::member_id(shipped) == id);
      ++checked;
    }
  }
  INFO("member scenes checked: " << checked);
  CHECK(checked > 500);
}
