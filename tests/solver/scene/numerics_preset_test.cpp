// The scene key `numerics: "dissertation"` (solver/scene/numerics_preset.hpp): every item the
// preset lists is the value the scene holds, a key the scene gives wins, and the toolkit's scenes
// keep their canonical text (their member ids).
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <sstream>

#include "solver/scene/numerics_preset.hpp"
#include "solver/scene/scene.hpp"

using capsule::Scene;
using capsule::SceneError;
using nlohmann::json;

namespace {
std::string short_number(double x) {
  std::ostringstream o;
  o << x;  // 10 -> "10", 0.025 -> "0.025"
  return o.str();
}

json scene(int dim, const std::string& shape) {
  return {{"dim", dim},
          {"shape", shape},
          {"Ca", 0.05},
          {"E_b", 0.01},
          {"V", 1},
          {"eta", 0},
          {"numerics", "dissertation"},
          {"protocol", {{"shear", {{"until", "steady"}}}, {"recover", {{"until", "time"}, {"kt", 5}}}}}};
}

// The canonical value of a dotted key, as the item lists write it ("[16, 12]", "0.025", "cosine").
std::string canonical_text(const json& canonical, const std::string& dotted) {
  json::json_pointer p("/" + [&] {
    std::string s = dotted;
    for (char& c : s)
      if (c == '.') c = '/';
    return s;
  }());
  const json& v = canonical.at(p);
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + short_number(v[i].get<double>());
    return text + "]";
  }
  return short_number(v.get<double>());
}
}  // namespace

TEST_CASE("numerics dissertation: every listed item is the value the scene runs", "[scene][numerics]") {
  for (const auto& [dim, shape] : std::vector<std::pair<int, std::string>>{
           {2, "circle"}, {2, "biconcave"}, {3, "sphere"}, {3, "biconcave"}}) {
    INFO(dim << "D " << shape);
    const Scene s = Scene::from_json(scene(dim, shape), "t.json");
    const json canonical = s.to_json();
    CHECK(canonical.at("numerics") == "dissertation");
    const auto items = capsule::dissertation_numerics_items(dim, s.shape);
    CHECK(items.size() >= 10);
    for (const auto& item : items) {
      INFO(item.key);
      CHECK(canonical_text(canonical, item.key) == item.value);
      CHECK_FALSE(item.source.empty());
    }
    CHECK(capsule::dissertation_numerics_gaps(dim).size() >= 5);
  }
  // The 2D biconcave capsule's size is an item of that shape only.
  const auto has = [](const std::vector<capsule::NumericsItem>& items, const std::string& key) {
    for (const auto& i : items)
      if (i.key == key) return true;
    return false;
  };
  CHECK(has(capsule::dissertation_numerics_items(2, capsule::Shape::biconcave), "conventions.biconcave_2d"));
  CHECK_FALSE(has(capsule::dissertation_numerics_items(2, capsule::Shape::circle), "conventions.biconcave_2d"));
}

TEST_CASE("numerics dissertation: the text's radius sets the lattice and the Reynolds number in k a^2 / nu", "[scene][numerics]") {
  // rho k a / mu_a = 0.05 with the printed a = 0.5 of the 2D biconcave capsule, and a = 1 for the
  // circle and the sphere; h = 0.05 (2D), 0.1 (3D).
  const Scene circle = Scene::from_json(scene(2, "circle"), "t.json");
  const Scene biconcave = Scene::from_json(scene(2, "biconcave"), "t.json");
  const Scene sphere = Scene::from_json(scene(3, "sphere"), "t.json");
  CHECK(circle.Re == 0.05);
  CHECK(circle.resolution.a == 20);
  CHECK(capsule::choice_name(circle.conventions.E_b_2d) == "dimensionless");
  CHECK(biconcave.Re == 0.025);
  CHECK(biconcave.resolution.a == 10);
  CHECK(capsule::choice_name(biconcave.conventions.E_b_2d) == "dissertation");
  CHECK(sphere.Re == 0.05);
  CHECK(sphere.resolution.a == 10);
}

TEST_CASE("numerics dissertation: a key the scene gives wins over the preset", "[scene][numerics]") {
  json j = scene(3, "sphere");
  j["resolution"] = {{"kernel", "roma3"}, {"marker_inset", "stresslet"}, {"a", 5}};
  j["Re"] = 0.1;
  const Scene s = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(s.resolution.delta) == "roma3");
  CHECK(s.resolution.marker_inset > 0.4);
  CHECK(s.resolution.a == 5);
  CHECK(s.Re == 0.1);
  CHECK(capsule::choice_name(s.resolution.collision) == "mrt");  // the other items stay the text's
  CHECK(s.to_json().at("numerics") == "dissertation");
}

TEST_CASE("numerics: the toolkit's scenes do not write the key - version 5 and unknown names refused", "[scene][numerics]") {
  json j = scene(2, "circle");
  j.erase("numerics");
  CHECK_FALSE(Scene::from_json(j, "t.json").to_json().contains("numerics"));
  j["numerics"] = "toolkit";
  CHECK_FALSE(Scene::from_json(j, "t.json").to_json().contains("numerics"));
  j["numerics"] = "dissertation";
  j["physics_version"] = "5";
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"),
                    Catch::Contains("t.json: numerics:") && Catch::Contains("physics_version"));
  j.erase("physics_version");
  j["numerics"] = "thesis";
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"),
                    Catch::Contains("numerics: unknown value") && Catch::Contains("toolkit | dissertation"));
}

TEST_CASE("resolution.kernel in 2D: peskin4 or the text's cosine - the 3D-only kernels refused", "[scene][numerics]") {
  json j = scene(2, "circle");
  j.erase("numerics");
  j["resolution"] = {{"kernel", "cosine"}};
  CHECK(capsule::choice_name(Scene::from_json(j, "t.json").resolution.delta) == "cosine");
  j["resolution"] = {{"kernel", "roma3"}};
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"),
                    Catch::Contains("resolution.kernel") && Catch::Contains("\"peskin4\" or \"cosine\" in 2D"));
}

TEST_CASE("numerics dissertation: the guide's table names every item the preset sets", "[scene][numerics]") {
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/docs/guide/dissertation_numerics.md");
  REQUIRE(in);
  const std::string guide((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const int dim : {2, 3})
    for (const auto& item : capsule::dissertation_numerics_items(dim, capsule::Shape::biconcave)) {
      INFO(dim << "D " << item.key);
      CHECK(guide.find("| `" + item.key + "` |") != std::string::npos);
    }
}
