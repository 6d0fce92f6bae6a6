// A cell in physical units: the conversion to (34)-(36) checked by hand, the canonical round
// trip, and every refusal naming the key and the allowed range.
#include <catch2/catch.hpp>
#include <string>

#include "solver/scene/physical_cell.hpp"
#include "solver/scene/scene.hpp"

using capsule::Scene;
using capsule::SceneError;
using nlohmann::json;

namespace {
// A red blood cell (volume-equivalent radius 2.82 um, G_s 6 uN/m, E_B 2e-19 J) in plasma at 180 1/s.
json rbc() {
  return json::parse(R"({"dim": 3, "shape": "biconcave", "law": "skalak",
    "physical": {"radius_um": 2.82, "shear_modulus_uN_per_m": 6.0, "bending_modulus_J": 2e-19,
                 "plasma_viscosity_mPa_s": 1.2, "cytoplasm_viscosity_mPa_s": 6.0,
                 "membrane_viscosity_uN_s_per_m": 0.6, "shear_rate_per_s": 180},
    "protocol": {"shear": {"until": "time", "kt": 1}, "recover": {"until": "time", "kt": 0}}})");
}

std::string refusal(const json& j) {
  try {
    Scene::from_json(j, "cell.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a physical cell gives the groups (34)-(36) computed by hand", "[scene][physical]") {
  const Scene s = Scene::from_json(rbc(), "cell.json");
  // Skalak: E_s = G_s. Ca = 1.2e-3 Pa s * 180/s * 2.82e-6 m / 6e-6 N/m = 0.10152.
  CHECK(s.Ca == Approx(0.10152).epsilon(1e-12));
  // E_b = 2e-19 J / ((2.82e-6 m)^2 * 6e-6 N/m) = 2e-19 / 4.77144e-17.
  CHECK(s.E_b == Approx(2e-19 / 4.77144e-17).epsilon(1e-12));
  CHECK(s.V == Approx(5.0).epsilon(1e-12));
  // eta = 0.6e-6 N s/m / (2.82e-6 m * 1.2e-3 Pa s) = 177.30...
  CHECK(s.eta == Approx(0.6e-6 / (2.82e-6 * 1.2e-3)).epsilon(1e-12));
  // The cell's own Re = 1000 * 180 * 2.82e-6^2 / 1.2e-3 = 1.19e-3 is below the default 0.05,
  // which the lattice runs at.
  const capsule::PhysicalGroups g = capsule::physical_groups(*s.physical, s.law, s.conventions.sls_viscosity);
  CHECK(g.Re == Approx(1000 * 180 * 2.82e-6 * 2.82e-6 / 1.2e-3).epsilon(1e-12));
  CHECK(s.Re == 0.05);
  CHECK(g.time_unit_s == Approx(1.0 / 180));
  CHECK(g.length_unit_um == 2.82);
}

TEST_CASE("neo-Hookean cells take E_s = 3 G_s, the dissertation's reading of (63) triples eta", "[scene][physical]") {
  json j = rbc();
  j["shape"] = "sphere";
  j["law"] = "neo-hookean";
  const Scene s = Scene::from_json(j, "cell.json");
  CHECK(s.Ca == Approx(0.10152 / 3).epsilon(1e-12));
  CHECK(s.E_b == Approx(2e-19 / 4.77144e-17 / 3).epsilon(1e-12));
  json d = rbc();
  d["conventions"] = {{"sls_viscosity", "dissertation"}};
  CHECK(Scene::from_json(d, "cell.json").eta == Approx(3 * 0.6e-6 / (2.82e-6 * 1.2e-3)).epsilon(1e-12));
}

TEST_CASE("a bending modulus in k_B T needs the temperature", "[scene][physical]") {
  json j = rbc();
  j["physical"].erase("bending_modulus_J");
  j["physical"]["bending_modulus_kT"] = 50;
  CHECK(refusal(j).find("physical.temperature_K: missing required key") != std::string::npos);
  j["physical"]["temperature_K"] = 310;
  // 50 * 1.380649e-23 J/K * 310 K = 2.13999e-19 J.
  CHECK(Scene::from_json(j, "cell.json").E_b == Approx(50 * 1.380649e-23 * 310 / 4.77144e-17).epsilon(1e-12));
  j["physical"]["bending_modulus_J"] = 2e-19;
  CHECK(refusal(j).find("physical.bending_modulus_kT: the bending modulus is given twice") != std::string::npos);
}

TEST_CASE("the canonical physical scene reads back to itself - a scene without one has no physical key", "[scene][physical]") {
  const json canonical = Scene::from_json(rbc(), "cell.json").to_json();
  REQUIRE(canonical.contains("physical"));
  CHECK(canonical["physical"]["radius_um"] == 2.82);
  CHECK(canonical["Ca"].get<double>() == Approx(0.10152).epsilon(1e-12));
  CHECK(Scene::from_json(canonical, "scene.json").to_json() == canonical);
  json plain = rbc();
  plain.erase("physical");
  plain["Ca"] = 0.1;
  plain["E_b"] = 0;
  plain["V"] = 1;
  plain["eta"] = 0;
  CHECK_FALSE(Scene::from_json(plain, "s.json").to_json().contains("physical"));
}

TEST_CASE("a group given beside the physical block must be the one it gives", "[scene][physical]") {
  json j = rbc();
  j["Ca"] = 0.2;
  const std::string why = refusal(j);
  CHECK(why.find("cell.json: Ca: Ca = 0.2 is not the physical block's 0.10152") != std::string::npos);
  CHECK(why.find("leave Ca out with a physical block") != std::string::npos);
}

TEST_CASE("bad physical input is refused naming the key and the allowed range", "[scene][physical]") {
  json j = rbc();
  j["physical"]["radius_um"] = -2;
  CHECK(refusal(j).find("physical.radius_um: value -2 out of range (allowed: (0, 1000])") != std::string::npos);
  j = rbc();
  j["physical"]["shear_rate_per_s"] = 0;
  CHECK(refusal(j).find("physical.shear_rate_per_s: value 0 out of range") != std::string::npos);
  j = rbc();
  j["physical"].erase("plasma_viscosity_mPa_s");
  CHECK(refusal(j).find("physical.plasma_viscosity_mPa_s: missing required key") != std::string::npos);
  j = rbc();
  j["physical"]["viscosity"] = 1;
  CHECK(refusal(j).find("physical.viscosity") != std::string::npos);
  // Ca = 1.2e-3 * 2e4 * 2.82e-6 / 6e-6 = 11.3: above the solver's range.
  j = rbc();
  j["physical"]["shear_rate_per_s"] = 2e4;
  std::string why = refusal(j);
  CHECK(why.find("physical: the cell gives Ca = 11.28") != std::string::npos);
  CHECK(why.find("Ca in (0, 10]") != std::string::npos);
  // A stiff, large cell at a high rate: Ca 0.012, but rho k a^2 / mu_a = 8333.
  j = rbc();
  j["physical"]["radius_um"] = 1000;
  j["physical"]["shear_modulus_uN_per_m"] = 1e6;
  j["physical"]["shear_rate_per_s"] = 1e4;
  j["physical"]["membrane_viscosity_uN_s_per_m"] = 0;
  j["physical"]["bending_modulus_J"] = 0;
  why = refusal(j);
  CHECK(why.find("physical.shear_rate_per_s: the cell's own Reynolds number") != std::string::npos);
  CHECK(why.find("rho k a^2 / mu_a <= 10") != std::string::npos);
  j = rbc();
  j["dim"] = 2;
  j["shape"] = "circle";
  j.erase("law");
  CHECK(refusal(j).find("cell.json: physical: physical units are for the 3D cell") != std::string::npos);
}

TEST_CASE("a cell whose own Re is above the lattice's floor runs at its own", "[scene][physical]") {
  json j = rbc();
  j["physical"]["radius_um"] = 100;
  j["physical"]["shear_rate_per_s"] = 100;
  j["physical"]["membrane_viscosity_uN_s_per_m"] = 0;
  j["physical"]["bending_modulus_J"] = 0;
  // 1000 * 100 * 1e-8 / 1.2e-3 = 0.8333.
  const Scene s = Scene::from_json(j, "cell.json");
  CHECK(s.Re == Approx(0.83333333).epsilon(1e-6));
  CHECK(Scene::from_json(s.to_json(), "scene.json").Re == s.Re);
}
