// Scenes: defaults, canonical form, and every refusal naming the key and the allowed range.
#include <catch2/catch.hpp>

#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

using capsule::Scene;
using capsule::SceneError;
using nlohmann::json;

namespace {
json minimal_2d() {
  return json::parse(R"({"dim": 2, "shape": "circle", "Ca": 0.04, "E_b": 0.05, "V": 1, "eta": 0,
    "protocol": {"shear": {"until": "steady"}, "recover": {"until": "time", "kt": 5}}})");
}
}  // namespace

TEST_CASE("a minimal scene gets the documented defaults", "[scene]") {
  Scene s = Scene::from_json(minimal_2d(), "t.json");
  CHECK(s.Re == 0.05);
  CHECK(s.a == 10);
  CHECK(s.domain == std::vector<double>{16, 12});
  CHECK(s.segments == 140);
  CHECK(s.law == "hooke");
  CHECK(s.grid() == std::vector<int>{160, 120, 1});
  json j = minimal_2d();
  j["dim"] = 3;
  j["shape"] = "biconcave";
  Scene t = Scene::from_json(j, "t.json");
  CHECK(t.law == "skalak");
  CHECK(t.kernel == "peskin4");
  j["resolution"] = {{"kernel", "roma3"}};
  CHECK(Scene::from_json(j, "t.json").kernel == "roma3");
  CHECK(t.grid() == std::vector<int>{100, 100, 80});
  CHECK(t.precision == "double");
}

TEST_CASE("resolution.precision: double by default, single selectable, only single in the canonical text", "[scene]") {
  json j = minimal_2d();
  const Scene d = Scene::from_json(j, "t.json");
  CHECK(d.precision == "double");
  // The default is left out of the canonical scene, so the ids of existing members stay.
  CHECK_FALSE(d.to_json()["resolution"].contains("precision"));
  j["resolution"] = {{"precision", "double"}};
  CHECK(Scene::from_json(j, "t.json").to_json() == d.to_json());
  j["resolution"] = {{"precision", "single"}};
  const Scene s = Scene::from_json(j, "t.json");
  CHECK(s.precision == "single");
  CHECK(s.to_json()["resolution"]["precision"] == "single");
  CHECK(Scene::from_json(s.to_json(), "t.json").precision == "single");
  j["resolution"] = {{"precision", "half"}};
  CHECK_THROWS_AS(Scene::from_json(j, "t.json"), SceneError);
}

TEST_CASE("the canonical scene does not depend on spelling, and round-trips", "[scene]") {
  json a = minimal_2d();
  json b = json::parse(R"({"eta": 0.0, "V": 1.0, "E_b": 5e-2, "Ca": 4e-2, "shape": "circle", "dim": 2,
    "resolution": {"a": 10.0},
    "protocol": {"recover": {"kt": 5.0, "until": "time"}, "shear": {"until": "steady"}}})");
  CHECK(Scene::from_json(a, "a").to_json().dump() == Scene::from_json(b, "b").to_json().dump());
  json c = Scene::from_json(a, "a").to_json();
  CHECK(Scene::from_json(c, "c").to_json() == c);
  json d = a;
  d["Ca"] = 0.0401;
  CHECK(Scene::from_json(d, "d").to_json().dump() != c.dump());
}

TEST_CASE("bad scenes are refused with the file, the key and the allowed range", "[scene]") {
  struct Bad {
    std::string what;
    std::function<void(json&)> edit;
    std::string expect;
  };
  std::vector<Bad> cases = {
      {"unknown key", [](json& j) { j["Caa"] = 1; }, "Caa: unknown key"},
      {"missing Ca", [](json& j) { j.erase("Ca"); }, "Ca: missing required key"},
      {"Ca <= 0", [](json& j) { j["Ca"] = 0; }, "Ca: value 0 out of range (allowed: (0, 10])"},
      {"V <= 0", [](json& j) { j["V"] = -1; }, "V: value -1 out of range"},
      {"wrong type", [](json& j) { j["E_b"] = "0.1"; }, "E_b: expected a number"},
      {"bad shape", [](json& j) { j["shape"] = "sphere"; }, "shape: unknown value \"sphere\" (allowed: circle | biconcave)"},
      {"unstable tau", [](json& j) { j["resolution"] = {{"tau", 0.5}}; }, "resolution.tau: relaxation time 0.5 cannot be run stably"},
      {"nested unknown", [](json& j) { j["protocol"]["shear"]["kt_max"] = 3; }, "protocol.shear.kt_max: unknown key"},
      {"missing protocol", [](json& j) { j.erase("protocol"); }, "protocol: missing required key"},
      {"time without kt", [](json& j) { j["protocol"]["recover"].erase("kt"); }, "protocol.recover.kt: missing required key"},
      {"domain length", [](json& j) { j["resolution"] = {{"domain", {16, 12, 8}}}; }, "resolution.domain: expected 2..2 entries"},
      {"case on a 2D scene", [](json& j) { j["reference_case"] = "A"; }, "reference_case: unknown value"},
      {"unknown kernel", [](json& j) { j["resolution"] = {{"kernel", "gauss"}}; },
       "resolution.kernel: unknown value \"gauss\" (allowed: peskin4 | roma3 | linear2 | cosine)"},
      {"3D-only kernel in 2D", [](json& j) { j["resolution"] = {{"kernel", "roma3"}}; },
       "resolution.kernel: kernel \"roma3\" is 3D only (allowed: \"peskin4\" in 2D)"},
  };
  for (const auto& c : cases) {
    SECTION(c.what) {
      json j = minimal_2d();
      c.edit(j);
      CHECK_THROWS_WITH(Scene::from_json(j, "scenes/x.json"),
                        Catch::StartsWith("scenes/x.json: ") && Catch::Contains(c.expect));
    }
  }
}

TEST_CASE("lattice units follow (8), (34)-(36) and Re = k a^2 / nu", "[scene]") {
  Scene s = Scene::from_json(minimal_2d(), "t.json");
  auto u = capsule::units_for(s, 1.0);
  CHECK(u.nu == Approx(1.0 / 6.0));
  CHECK(u.shear_rate * s.a * s.a / u.nu == Approx(s.Re));
  CHECK(u.nu * u.shear_rate * s.a / u.E_s == Approx(s.Ca));
  CHECK(u.E_B / (s.a * s.a * u.E_s) == Approx(s.E_b));  // dimensionless form, README "Conventions"
  CHECK_THROWS(capsule::units_for(s, 0.5));
}
