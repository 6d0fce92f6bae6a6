// protocol.stretch (solver/scene/stretch_scene.hpp): the canonical round trip, the force in pN of
// a physical cell, and every refusal naming the key and the allowed range.
#include <catch2/catch.hpp>
#include <string>

#include "solver/scene/physical_cell.hpp"
#include "solver/scene/scene.hpp"

using capsule::Scene;
using capsule::SceneError;
using nlohmann::json;

namespace {
json sphere(const json& stretch) {
  return {{"dim", 3}, {"shape", "sphere"}, {"Ca", 0.05}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
          {"protocol", {{"stretch", stretch}, {"recover", {{"until", "time"}, {"kt", 1.0}}}}}};
}

std::string refusal(const json& j) {
  try {
    Scene::from_json(j, "pull.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a stretch protocol reads its load and round-trips through the canonical scene", "[scene][stretch]") {
  const Scene s = Scene::from_json(sphere({{"force", 0.1}, {"until", "steady"}, {"tolerance", 1e-4}}), "pull.json");
  REQUIRE(s.protocol.stretch);
  CHECK(s.protocol.stretch->force == 0.1);
  CHECK(s.protocol.stretch->patch_fraction == 0.02);  // Fedosov et al.'s 2 % by default
  CHECK(s.protocol.shear.until == capsule::StopCondition::steady);
  CHECK(s.protocol.shear.tolerance == 1e-4);
  const json canonical = s.to_json();
  CHECK(!canonical["protocol"].contains("shear"));
  CHECK(canonical["protocol"]["stretch"]["force"] == 0.1);
  CHECK(canonical["protocol"]["stretch"]["patch_fraction"] == 0.02);
  CHECK(Scene::from_json(canonical, "again").to_json() == canonical);
  const Scene d = Scene::from_json(sphere({{"force", 0.1}, {"contact_diameter", 0.5}, {"until", "time"}, {"kt", 3}}), "pull.json");
  CHECK(d.protocol.stretch->contact_diameter == 0.5);
  CHECK(d.protocol.stretch->patch_fraction == 0.0);
  CHECK(d.protocol.shear.kt == 3.0);
  CHECK(Scene::from_json(d.to_json(), "again").to_json() == d.to_json());
}

TEST_CASE("a scene without a stretch protocol has no stretch in its canonical text", "[scene][stretch]") {
  json j = sphere({});
  j["protocol"] = {{"shear", {{"until", "time"}, {"kt", 1}}}, {"recover", {{"until", "time"}, {"kt", 1}}}};
  const Scene s = Scene::from_json(j, "shear.json");
  CHECK(!s.protocol.stretch);
  CHECK(s.to_json()["protocol"].size() == 2);
  CHECK(s.to_json()["protocol"].contains("shear"));
}

TEST_CASE("a physical cell's force in pN is F / (E_s a) computed by hand, both kept", "[scene][stretch][physical]") {
  json j = json::parse(R"({"dim": 3, "shape": "biconcave", "law": "skalak", "C": 100,
    "physical": {"radius_um": 2.82, "shear_modulus_uN_per_m": 5.5, "bending_modulus_J": 2e-19,
                 "plasma_viscosity_mPa_s": 1.0, "shear_rate_per_s": 100},
    "protocol": {"stretch": {"force_pN": 88, "contact_diameter_um": 2.0, "until": "steady"},
                 "recover": {"until": "time", "kt": 0}}})");
  const Scene s = Scene::from_json(j, "cell.json");
  // Skalak: E_s = G_s = 5.5e-6 N/m; F / (E_s a) = 88e-12 / (5.5e-6 * 2.82e-6) = 5.6738...
  CHECK(s.protocol.stretch->force == Approx(88e-12 / (5.5e-6 * 2.82e-6)).epsilon(1e-12));
  CHECK(s.protocol.stretch->force_pN == 88.0);
  CHECK(s.protocol.stretch->contact_diameter == Approx(2.0 / 2.82).epsilon(1e-12));
  const json canonical = s.to_json();
  CHECK(canonical["protocol"]["stretch"]["force_pN"] == 88.0);
  CHECK(canonical["protocol"]["stretch"]["contact_diameter_um"] == 2.0);
  CHECK(!canonical["protocol"]["stretch"].contains("force"));
  CHECK(Scene::from_json(canonical, "again").to_json() == canonical);
}

TEST_CASE("a force of 0 pN stays in pN in the canonical scene, as a campaign sweeping force_pN finds it",
          "[scene][stretch][physical]") {
  json j = json::parse(R"({"dim": 3, "shape": "biconcave", "law": "skalak", "C": 100,
    "physical": {"radius_um": 2.82, "shear_modulus_uN_per_m": 5.5, "bending_modulus_J": 2e-19,
                 "plasma_viscosity_mPa_s": 1.0, "shear_rate_per_s": 100},
    "protocol": {"stretch": {"force_pN": 0, "contact_diameter_um": 2.0, "until": "steady"},
                 "recover": {"until": "time", "kt": 0}}})");
  const json canonical = Scene::from_json(j, "cell.json").to_json();
  CHECK(canonical["protocol"]["stretch"]["force_pN"] == 0.0);
  CHECK(!canonical["protocol"]["stretch"].contains("force"));
  CHECK(Scene::from_json(canonical, "again").to_json() == canonical);
}

TEST_CASE("bad stretch protocols are refused naming the key and the allowed range", "[scene][stretch]") {
  const json ok = {{"force", 0.1}, {"until", "steady"}};
  auto with = [&](const std::string& key, const json& value) {
    json s = ok;
    s[key] = value;
    return sphere(s);
  };
  CHECK_THAT(refusal(with("force", -0.1)),
             Catch::Contains("pull.json: protocol.stretch.force: value -0.1 out of range (allowed: [0, 1000])"));
  CHECK_THAT(refusal(with("patch_fraction", 0.5)),
             Catch::Contains("protocol.stretch.patch_fraction: value 0.5 out of range (allowed: (0, 0.5))"));
  CHECK_THAT(refusal(with("patch_fraction", 0.0)), Catch::Contains("(allowed: (0, 0.5))"));
  CHECK_THAT(refusal(with("contact_diameter", 3.0)),
             Catch::Contains("protocol.stretch.contact_diameter: value 3 out of range (allowed: (0, 2])"));
  CHECK_THAT(refusal(with("until", "theta")), Catch::Contains("protocol.stretch.until: unknown value \"theta\" (allowed: time | steady)"));
  CHECK_THAT(refusal(with("forc", 1.0)), Catch::Contains("protocol.stretch.forc: unknown key, did you mean force?"));
  json two_patches = ok;
  two_patches["patch_fraction"] = 0.02;
  two_patches["contact_diameter"] = 0.5;
  CHECK_THAT(refusal(sphere(two_patches)), Catch::Contains("protocol.stretch.contact_diameter: given together with patch_fraction"));
  CHECK_THAT(refusal(with("force_pN", 10.0)), Catch::Contains("protocol.stretch.force_pN: given together with force"));
  json pN = ok;
  pN.erase("force");
  pN["force_pN"] = 10.0;
  CHECK_THAT(refusal(sphere(pN)), Catch::Contains("protocol.stretch.force_pN: a value in physical units needs the scene's physical block"));
  json missing = ok;
  missing.erase("force");
  CHECK_THAT(refusal(sphere(missing)), Catch::Contains("protocol.stretch.force: missing required key"));
  json two_d = {{"dim", 2}, {"shape", "circle"}, {"Ca", 0.05}, {"E_b", 0.0}, {"V", 1.0}, {"eta", 0.0},
                {"protocol", {{"stretch", ok}, {"recover", {{"until", "time"}, {"kt", 1.0}}}}}};
  CHECK_THAT(refusal(two_d), Catch::Contains("pull.json: protocol.stretch: the stretch protocol pulls a 3D membrane (allowed: a stretch protocol with dim 3 only)"));
  json both = sphere(ok);
  both["protocol"]["shear"] = {{"until", "time"}, {"kt", 1}};
  CHECK_THAT(refusal(both), Catch::Contains("protocol.stretch: a protocol shears or stretches, not both"));
}
