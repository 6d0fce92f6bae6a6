// Scenes: defaults, canonical form, and every refusal naming the key and the allowed range.
#include <catch2/catch.hpp>
#include <cmath>

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
  CHECK(s.resolution.a == 10);
  CHECK(s.resolution.domain == std::vector<double>{16, 12});
  CHECK(s.resolution.segments == 140);
  CHECK(capsule::choice_name(s.law) == "hooke");
  CHECK(s.grid() == std::vector<int>{160, 120, 1});
  json j = minimal_2d();
  j["dim"] = 3;
  j["shape"] = "biconcave";
  Scene t = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(t.law) == "skalak");
  // Physics version 6: roma3 with the stresslet's inset, trt; version 5 kept peskin4 on a, mrt.
  CHECK(capsule::choice_name(t.resolution.delta) == "roma3");
  CHECK(capsule::choice_name(t.resolution.marker_inset_rule) == "stresslet");
  CHECK(t.resolution.marker_inset == Approx(0.4287).margin(1e-4));
  CHECK(capsule::choice_name(t.resolution.collision) == "trt");
  CHECK(capsule::choice_name(t.power_law.model) == "membrane");
  CHECK(capsule::choice_name(s.resolution.kelvin_voigt_step) == "exact_mobility");
  j["resolution"] = {{"kernel", "peskin4"}};
  CHECK(capsule::choice_name(Scene::from_json(j, "t.json").resolution.delta) == "peskin4");
  CHECK(Scene::from_json(j, "t.json").resolution.marker_inset == Approx(0.5943).margin(1e-4));
  json v5 = j;
  v5["physics_version"] = "5";
  v5["resolution"] = json::object();
  const Scene old = Scene::from_json(v5, "t.json");
  CHECK(capsule::choice_name(old.resolution.delta) == "peskin4");
  CHECK(old.resolution.marker_inset == 0.0);
  CHECK(capsule::choice_name(old.resolution.collision) == "mrt");
  CHECK(capsule::choice_name(old.power_law.model) == "fluid_shell");
  CHECK(t.grid() == std::vector<int>{100, 100, 80});
  CHECK(capsule::choice_name(s.conventions.sls_viscosity) == "physical");
  CHECK(capsule::choice_name(s.conventions.E_b_2d) == "dimensionless");
  CHECK(s.to_json()["conventions"] == json{{"sls_viscosity", "physical"}, {"E_b_2d", "dimensionless"}, {"biconcave_2d", "equivalent"}});
  json settled = minimal_2d();
  settled["protocol"]["recover"] = {{"until", "settled"}};
  CHECK(Scene::from_json(settled, "t.json").protocol.recover.window_fraction == 0.5);
  json j3 = j;
  j3["conventions"] = {{"E_b_2d", "dissertation"}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"), Catch::Contains("conventions.E_b_2d: the 2D bending convention"));
  CHECK(capsule::choice_name(t.resolution.precision) == "single");  // 3D default (the precision comparison)
  // biconcave_2d: in version 5's canonical text only when set (member ids made before it
  // stay), always from version 6; refused where it means nothing.
  CHECK(capsule::choice_name(s.conventions.biconcave_2d) == "equivalent");
  json s5 = minimal_2d();
  s5["physics_version"] = 5;
  CHECK(!Scene::from_json(s5, "t.json").to_json()["conventions"].contains("biconcave_2d"));
  json b = minimal_2d();
  b["shape"] = "biconcave";
  b["conventions"] = {{"biconcave_2d", "dissertation"}};
  const Scene sb = Scene::from_json(b, "t.json");
  CHECK(sb.to_json()["conventions"]["biconcave_2d"] == "dissertation");
  CHECK(capsule::choice_name(Scene::from_json(sb.to_json(), "t.json").conventions.biconcave_2d) == "dissertation");
  b["shape"] = "circle";
  CHECK_THROWS_WITH(Scene::from_json(b, "t.json"),
                    Catch::Contains("conventions.biconcave_2d") && Catch::Contains("2D biconcave capsule only"));
}

TEST_CASE("a Scene built in code has the parser's defaults of a 2D scene of today's physics", "[scene]") {
  // One defaults table (scene_defaults): the in-class defaults and the parser's agree.
  const Scene in_code;
  const Scene parsed = Scene::from_json(minimal_2d(), "t.json");
  CHECK(in_code.dim == parsed.dim);
  CHECK(in_code.physics_version == parsed.physics_version);
  CHECK(in_code.resolution.delta == parsed.resolution.delta);
  CHECK(in_code.resolution.collision == parsed.resolution.collision);
  CHECK(in_code.resolution.precision == parsed.resolution.precision);
  CHECK(in_code.power_law.model == parsed.power_law.model);
  CHECK(in_code.resolution.kelvin_voigt_step == parsed.resolution.kelvin_voigt_step);
  CHECK(in_code.resolution.marker_inset_rule == parsed.resolution.marker_inset_rule);
  CHECK(in_code.resolution.membrane_update == parsed.resolution.membrane_update);
  CHECK(in_code.resolution.domain == parsed.resolution.domain);
  CHECK(in_code.resolution.segments == parsed.resolution.segments);
  CHECK(in_code.resolution.mesh_level == parsed.resolution.mesh_level);
  // And each (version, dimension) row of the table is what the parser gives that scene.
  for (const auto version : {capsule::PhysicsVersion::current, capsule::PhysicsVersion::v5}) {
    for (const int dim : {2, 3}) {
      json j = minimal_2d();
      if (dim == 3) {
        j["dim"] = 3;
        j["shape"] = "sphere";
      }
      j["physics_version"] = capsule::choice_name(version);
      const Scene s = Scene::from_json(j, "t.json");
      const capsule::SceneDefaults d = capsule::scene_defaults(version, dim);
      INFO("physics version " << capsule::choice_name(version) << ", " << dim << "D");
      CHECK(s.resolution.delta == d.delta);
      CHECK(s.resolution.collision == d.collision);
      CHECK(s.resolution.precision == d.precision);
      CHECK(s.power_law.model == d.power_law_model);
      CHECK(s.resolution.kelvin_voigt_step == d.kelvin_voigt_step);
      CHECK(s.resolution.marker_inset_rule == d.marker_inset_rule);
      CHECK(s.resolution.domain == d.domain);
    }
  }
}

TEST_CASE("resolution.precision: 2D double by default (version 5 wrote only single) - 3D single by default, always written", "[scene]") {
  json j3 = minimal_2d();
  j3["dim"] = 3;
  j3["shape"] = "sphere";
  const Scene s3 = Scene::from_json(j3, "t.json");
  CHECK(capsule::choice_name(s3.resolution.precision) == "single");
  CHECK(s3.to_json()["resolution"]["precision"] == "single");
  j3["resolution"] = {{"precision", "double"}};
  const Scene d3 = Scene::from_json(j3, "t.json");
  CHECK(capsule::choice_name(d3.resolution.precision) == "double");
  CHECK(d3.to_json()["resolution"]["precision"] == "double");
  // The canonical text must run as what it says: it is the scene.json a member is run from.
  CHECK(capsule::choice_name(Scene::from_json(d3.to_json(), "t.json").resolution.precision) == "double");
  CHECK(capsule::choice_name(Scene::from_json(s3.to_json(), "t.json").resolution.precision) == "single");

  // Version 6 writes it always; version 5 left the 2D default out (its members' ids stay).
  CHECK(Scene::from_json(minimal_2d(), "t.json").to_json()["resolution"]["precision"] == "double");
  json j = minimal_2d();
  j["physics_version"] = "5";
  const Scene d = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(d.resolution.precision) == "double");
  CHECK_FALSE(d.to_json()["resolution"].contains("precision"));
  j["resolution"] = {{"precision", "double"}};
  CHECK(Scene::from_json(j, "t.json").to_json() == d.to_json());
  j["resolution"] = {{"precision", "single"}};
  const Scene s = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(s.resolution.precision) == "single");
  CHECK(s.to_json()["resolution"]["precision"] == "single");
  CHECK(capsule::choice_name(Scene::from_json(s.to_json(), "t.json").resolution.precision) == "single");
  j["resolution"] = {{"precision", "half"}};
  CHECK_THROWS_AS(Scene::from_json(j, "t.json"), SceneError);
}

TEST_CASE("resolution.membrane_update: euler by default (left out of version 5's canonical text) - 3D only", "[scene]") {
  json j3 = minimal_2d();
  j3["dim"] = 3;
  j3["shape"] = "sphere";
  CHECK(Scene::from_json(j3, "t.json").to_json()["resolution"]["membrane_update"] == "euler");
  j3["physics_version"] = "5";
  const Scene e = Scene::from_json(j3, "t.json");
  CHECK(capsule::choice_name(e.resolution.membrane_update) == "euler");
  // Version 5 did not write the default, so the ids of members run before the key existed stay.
  CHECK_FALSE(e.to_json()["resolution"].contains("membrane_update"));
  j3["resolution"] = {{"membrane_update", "euler"}};
  CHECK(Scene::from_json(j3, "t.json").to_json() == e.to_json());
  for (const std::string name : {"previous_velocity", "adams_bashforth2"}) {
    j3["resolution"] = {{"membrane_update", name}};
    const Scene s = Scene::from_json(j3, "t.json");
    CHECK(capsule::choice_name(s.resolution.membrane_update) == name);
    CHECK(s.to_json()["resolution"]["membrane_update"] == name);
    CHECK(capsule::choice_name(Scene::from_json(s.to_json(), "t.json").resolution.membrane_update) == name);  // runs as it says
  }
  j3["resolution"] = {{"membrane_update", "runge_kutta4"}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"),
                    Catch::Contains("resolution.membrane_update: unknown value \"runge_kutta4\""));
  json j2 = minimal_2d();
  j2["resolution"] = {{"membrane_update", "adams_bashforth2"}};
  CHECK_THROWS_WITH(Scene::from_json(j2, "t.json"),
                    Catch::Contains("resolution.membrane_update: membrane update \"adams_bashforth2\" is 3D only"));
}

TEST_CASE("resolution.marker_inset: the stresslet's rule by default in 3D (0 in version 5 and in 2D) - a number - at most a/4", "[scene]") {
  json j3 = minimal_2d();
  j3["dim"] = 3;
  j3["shape"] = "sphere";
  // Version 6: the rule, written by its name; its value from a and the kernel.
  const Scene r = Scene::from_json(j3, "t.json");
  CHECK(capsule::choice_name(r.resolution.marker_inset_rule) == "stresslet");
  CHECK(r.to_json()["resolution"]["marker_inset"] == "stresslet");
  CHECK(Scene::from_json(r.to_json(), "t.json").resolution.marker_inset == r.resolution.marker_inset);  // runs as it says
  j3["resolution"] = {{"a", 5.0}, {"marker_inset", "stresslet"}};
  CHECK(Scene::from_json(j3, "t.json").resolution.marker_inset == Approx(0.5263).margin(1e-4));
  // A kernel whose shell was not measured gets 0 by default and refuses the rule.
  j3["resolution"] = {{"kernel", "linear2"}};
  CHECK(Scene::from_json(j3, "t.json").resolution.marker_inset == 0.0);
  CHECK(Scene::from_json(j3, "t.json").to_json()["resolution"]["marker_inset"] == 0.0);
  j3["resolution"] = {{"kernel", "linear2"}, {"marker_inset", "stresslet"}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"),
                    Catch::Contains("resolution.marker_inset") && Catch::Contains("peskin4, roma3 and keys4"));
  // Below the smallest radius the rule has no solution: the scene says where it has one.
  j3["resolution"] = {{"a", 2.0}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"), Catch::Contains("resolution.marker_inset") && Catch::Contains("a >= 2.15"));
  j3["resolution"] = {{"marker_inset", "torque"}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"), Catch::Contains("resolution.marker_inset") && Catch::Contains("\"stresslet\" or a number"));
  // Version 5: 0 by default, not written, so the ids of members run before the key existed stay.
  j3["physics_version"] = "5";
  j3["resolution"] = json::object();
  const Scene e = Scene::from_json(j3, "t.json");
  CHECK(e.resolution.marker_inset == 0.0);
  CHECK_FALSE(e.to_json()["resolution"].contains("marker_inset"));
  j3["resolution"] = {{"marker_inset", 0.0}};
  CHECK(Scene::from_json(j3, "t.json").to_json() == e.to_json());
  j3.erase("physics_version");
  j3["resolution"] = {{"a", 10.0}, {"marker_inset", 0.45}};
  const Scene s = Scene::from_json(j3, "t.json");
  CHECK(s.to_json()["resolution"]["marker_inset"] == 0.45);
  CHECK(Scene::from_json(s.to_json(), "t.json").resolution.marker_inset == 0.45);
  j3["resolution"] = {{"a", 4.0}, {"marker_inset", 1.5}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"), Catch::Contains("resolution.marker_inset") && Catch::Contains("[0, a/4]"));
  j3["resolution"] = {{"marker_inset", -0.1}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"), Catch::Contains("resolution.marker_inset"));
  json j2 = minimal_2d();
  CHECK(Scene::from_json(j2, "t.json").resolution.marker_inset == 0.0);
  CHECK(Scene::from_json(j2, "t.json").to_json()["resolution"]["marker_inset"] == 0.0);
  j2["resolution"] = {{"marker_inset", 0.5}};
  CHECK(Scene::from_json(j2, "t.json").resolution.marker_inset == 0.5);  // a scene choice in 2D
}

TEST_CASE("resolution.kelvin_voigt_step: exact_mobility by default (version 5: approximate_mobility, left out of its canonical text) - 2D only",
          "[scene]") {
  json j = minimal_2d();
  j["eta"] = 200;
  CHECK(capsule::choice_name(Scene::from_json(j, "t.json").resolution.kelvin_voigt_step) == "exact_mobility");
  CHECK(Scene::from_json(j, "t.json").to_json()["resolution"]["kelvin_voigt_step"] == "exact_mobility");
  j["physics_version"] = "5";
  const Scene d = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(d.resolution.kelvin_voigt_step) == "approximate_mobility");
  // The default is not written, so the ids of members run before the key existed stay.
  CHECK_FALSE(d.to_json()["resolution"].contains("kelvin_voigt_step"));
  CHECK(Scene::omitted_defaults(2).at("resolution.kelvin_voigt_step") == "approximate_mobility");
  CHECK(Scene::omitted_defaults(3).at("resolution.kelvin_voigt_step") == "approximate_mobility");
  j["resolution"] = {{"kelvin_voigt_step", "approximate_mobility"}};
  CHECK(Scene::from_json(j, "t.json").to_json() == d.to_json());
  j["resolution"] = {{"kelvin_voigt_step", "exact_mobility"}};
  const Scene e = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(e.resolution.kelvin_voigt_step) == "exact_mobility");
  CHECK(e.to_json()["resolution"]["kelvin_voigt_step"] == "exact_mobility");
  CHECK(capsule::choice_name(Scene::from_json(e.to_json(), "t.json").resolution.kelvin_voigt_step) == "exact_mobility");  // runs as it says
  CHECK(e.to_json() != d.to_json());  // another member id
  j["resolution"] = {{"kelvin_voigt_step", "exact"}};
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"),
                    Catch::Contains("resolution.kelvin_voigt_step: unknown value \"exact\"") &&
                        Catch::Contains("approximate_mobility | exact_mobility"));
  j["resolution"] = {{"kelvin_voigt_step", 1}};
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"), Catch::Contains("resolution.kelvin_voigt_step: expected a string"));
  json j3 = minimal_2d();
  j3["dim"] = 3;
  j3["shape"] = "sphere";
  CHECK(capsule::choice_name(Scene::from_json(j3, "t.json").resolution.kelvin_voigt_step) == "approximate_mobility");
  j3["physics_version"] = "5";
  j3["resolution"] = {{"kelvin_voigt_step", "approximate_mobility"}};
  CHECK_FALSE(Scene::from_json(j3, "t.json").to_json()["resolution"].contains("kelvin_voigt_step"));
  j3["resolution"] = {{"kelvin_voigt_step", "exact_mobility"}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"),
                    Catch::Contains("resolution.kelvin_voigt_step: Kelvin-Voigt step \"exact_mobility\" is the 2D membrane's"));
}

TEST_CASE("power_law.model: membrane by default (version 5: fluid_shell, left out of its canonical text) - membrane replaces eta", "[scene]") {
  json j = minimal_2d();
  j["dim"] = 3;
  j["shape"] = "sphere";
  j["power_law"] = {{"K", 10}, {"n", 0.64}};
  CHECK(capsule::choice_name(Scene::from_json(j, "t.json").power_law.model) == "membrane");
  CHECK(Scene::from_json(j, "t.json").to_json()["power_law"]["model"] == "membrane");
  j["physics_version"] = "5";
  const Scene d = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(d.power_law.model) == "fluid_shell");
  // The default is not written, so the ids of members run before the key existed stay.
  CHECK_FALSE(d.to_json()["power_law"].contains("model"));
  CHECK(Scene::omitted_defaults(3).at("power_law.model") == "fluid_shell");
  j["power_law"]["model"] = "fluid_shell";
  CHECK(Scene::from_json(j, "t.json").to_json() == d.to_json());
  j["power_law"]["model"] = "membrane";
  const Scene m = Scene::from_json(j, "t.json");
  CHECK(capsule::choice_name(m.power_law.model) == "membrane");
  CHECK(m.to_json()["power_law"]["model"] == "membrane");
  CHECK(capsule::choice_name(Scene::from_json(m.to_json(), "t.json").power_law.model) == "membrane");  // runs as it says
  CHECK(m.to_json() != d.to_json());  // another member id
  // Without a power law the key means nothing, and does not move the id.
  j["power_law"] = {{"K", 0}, {"model", "membrane"}};
  CHECK_FALSE(Scene::from_json(j, "t.json").to_json()["power_law"].contains("model"));
  // The membrane reading is the SLS's own viscous element: not beside eta.
  j["power_law"] = {{"K", 10}, {"model", "membrane"}};
  j["eta"] = 2;
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"), Catch::Contains("power_law.model") && Catch::Contains("eta = 0 with model"));
  j["eta"] = 0;
  j["power_law"]["model"] = "shell";
  CHECK_THROWS_WITH(Scene::from_json(j, "t.json"), Catch::Contains("power_law.model: unknown value \"shell\""));
}

TEST_CASE("resolution.collision: trt by default in 3D (version 5: mrt, left out of its canonical text) - trt 3D only", "[scene]") {
  json j3 = minimal_2d();
  j3["dim"] = 3;
  j3["shape"] = "sphere";
  j3["V"] = 5;
  CHECK(capsule::choice_name(Scene::from_json(j3, "t.json").resolution.collision) == "trt");
  CHECK(capsule::choice_name(Scene::from_json(minimal_2d(), "t.json").resolution.collision) == "mrt");
  j3["physics_version"] = "5";
  const Scene d = Scene::from_json(j3, "t.json");
  CHECK(capsule::choice_name(d.resolution.collision) == "mrt");
  // The default is not written, so the ids of members run before the key existed stay.
  CHECK_FALSE(d.to_json()["resolution"].contains("collision"));
  CHECK(Scene::omitted_defaults(2).at("resolution.collision") == "mrt");
  CHECK(Scene::omitted_defaults(3).at("resolution.collision") == "mrt");
  j3["resolution"] = {{"collision", "mrt"}};
  CHECK(Scene::from_json(j3, "t.json").to_json() == d.to_json());
  j3["resolution"] = {{"collision", "trt"}};
  const Scene t = Scene::from_json(j3, "t.json");
  CHECK(capsule::choice_name(t.resolution.collision) == "trt");
  CHECK(t.to_json()["resolution"]["collision"] == "trt");
  CHECK(capsule::choice_name(Scene::from_json(t.to_json(), "t.json").resolution.collision) == "trt");  // runs as it says
  CHECK(t.to_json() != d.to_json());                                  // another member id
  j3["resolution"] = {{"collision", "bgk"}};
  CHECK_THROWS_WITH(Scene::from_json(j3, "t.json"),
                    Catch::Contains("resolution.collision: unknown value \"bgk\"") && Catch::Contains("mrt | trt"));
  json j2 = minimal_2d();
  j2["resolution"] = {{"collision", "trt"}};
  j2["physics_version"] = "5";
  CHECK_THROWS_WITH(Scene::from_json(j2, "t.json"), Catch::Contains("resolution.collision: the 2D rates (9)"));
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
       "resolution.kernel: unknown value \"gauss\" (allowed: peskin4 | roma3 | linear2 | cosine | keys4)"},
      {"3D-only kernel in 2D", [](json& j) { j["resolution"] = {{"kernel", "roma3"}}; },
       "resolution.kernel: kernel \"roma3\" is 3D only (allowed: \"peskin4\" or \"cosine\" in 2D)"},
      {"SLS convention in 2D", [](json& j) { j["conventions"] = {{"sls_viscosity", "dissertation"}}; },
       "conventions.sls_viscosity: the standard linear solid is the 3D membrane's (allowed: \"physical\" in 2D)"},
      {"unknown convention", [](json& j) { j["conventions"] = {{"E_b_2d", "text"}}; },
       "conventions.E_b_2d: unknown value \"text\" (allowed: dimensionless | dissertation)"},
      {"unknown physics version", [](json& j) { j["physics_version"] = "4"; },
       "physics_version: physics version \"4\" is not one this solver runs"},
      {"window_fraction on a timed recovery", [](json& j) { j["protocol"]["recover"]["window_fraction"] = 0.5; },
       "protocol.recover.window_fraction: value 0.5 out of range (allowed: [0, 0])"},
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
  CHECK(u.shear_rate * s.resolution.a * s.resolution.a / u.nu == Approx(s.Re));
  CHECK(u.nu * u.shear_rate * s.resolution.a / u.E_s == Approx(s.Ca));
  CHECK(u.E_B / (s.resolution.a * s.resolution.a * u.E_s) == Approx(s.E_b));  // dimensionless form, docs/conventions.md "E_b"
  CHECK_THROWS(capsule::units_for(s, 0.5));
}


TEST_CASE("the membrane's bending modulus is that of the circle or sphere its nodes form", "[scene]") {
  // Without an inset it is units.E_B to the bit (the members run before the helper keep their numbers).
  json j2 = minimal_2d();
  const Scene plain = Scene::from_json(j2, "t.json");
  const auto u = capsule::units_for(plain, 1.0);
  CHECK(capsule::membrane_bending_modulus(plain, u) == u.E_B);
  // Nodes on r_m = a - inset: E_B = E_b r_m^2 E_s, and the 2D dissertation convention's factor 2 stays.
  j2["resolution"] = {{"a", 10.0}, {"marker_inset", 0.5}};
  j2["conventions"] = {{"E_b_2d", "dissertation"}};
  const Scene inset_2d = Scene::from_json(j2, "t.json");
  const auto u2 = capsule::units_for(inset_2d, 1.0);
  CHECK(capsule::membrane_bending_modulus(inset_2d, u2) / (9.5 * 9.5 * u2.E_s) == Approx(2.0 * inset_2d.E_b).epsilon(1e-14));
  json j3 = minimal_2d();
  j3["dim"] = 3;
  j3["shape"] = "sphere";
  j3["resolution"] = {{"a", 7.0}};  // the stresslet's inset, about 0.47
  const Scene sphere = Scene::from_json(j3, "t.json");
  const auto u3 = capsule::units_for(sphere, 1.0);
  const double r_m = 7.0 - sphere.resolution.marker_inset;
  CHECK(sphere.resolution.marker_inset > 0.4);
  CHECK(capsule::membrane_bending_modulus(sphere, u3) == Approx(sphere.E_b * r_m * r_m * u3.E_s).epsilon(1e-14));
  CHECK(capsule::membrane_bending_modulus(sphere, u3) < u3.E_B);
}
TEST_CASE("3D relaxation-time rule: tau = 1.5 where stable, lowered by the coupling bounds", "[scene]") {
  auto sphere = [](double Ca, double E_b, double a) {
    json j = json::parse(R"({"dim": 3, "shape": "sphere", "V": 1, "eta": 0,
      "protocol": {"shear": {"until": "steady"}, "recover": {"until": "settled"}}})");
    j["Ca"] = Ca;
    j["E_b"] = E_b;
    j["resolution"] = {{"a", a}};
    if (a < 2.2) j["resolution"]["marker_inset"] = 0.0;  // the stresslet's inset needs a >= 2.15
    return Scene::from_json(j, "t.json");
  };
  // The default 3D member (a = 10, Re = 0.05, Ca = 0.05, E_b = 0.025): at most 6000 steps per kt.
  const Scene ref = sphere(0.05, 0.025, 10);
  CHECK(capsule::choose_tau(ref) == Approx(1.5));
  CHECK(capsule::units_for(ref, capsule::choose_tau(ref)).steps_per_kt == Approx(6000.0));
  // Bending number B = E_b a Re nu / Ca capped at 0.17 (E_b = 0.1: the stable tau = 1 of Fig. 8).
  const Scene stiff = sphere(0.05, 0.1, 10);
  const double nu_stiff = (capsule::choose_tau(stiff) - 0.5) / 3.0;
  CHECK(stiff.E_b * stiff.resolution.a * stiff.Re * nu_stiff / stiff.Ca == Approx(0.17));
  // Elastic number S = Re nu / (a Ca) capped at 0.17 (small Ca).
  const Scene soft = sphere(0.005, 0.0, 10);
  const double nu_soft = (capsule::choose_tau(soft) - 0.5) / 3.0;
  CHECK(soft.Re * nu_soft / (soft.resolution.a * soft.Ca) == Approx(0.17));
  // A more viscous interior: with the trt rates (version 6) its D does not depend on tau, so it
  // takes tau = 1.5 as well; with the mrt rates (version 5) the error depends on the inside
  // relaxation time and tau stays 1.
  json v5 = ref.to_json();
  v5["V"] = 5.0;
  CHECK(capsule::choose_tau(Scene::from_json(v5, "t.json")) == Approx(1.5));
  v5["resolution"]["collision"] = "mrt";
  CHECK(capsule::choose_tau(Scene::from_json(v5, "t.json")) == Approx(1.0));
  json v5_version5 = json::parse(R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0.025, "V": 5, "eta": 0, "physics_version": "5",
      "protocol": {"shear": {"until": "steady"}, "recover": {"until": "settled"}}})");
  CHECK(capsule::choose_tau(Scene::from_json(v5_version5, "t.json")) == Approx(1.0));
  json v02 = ref.to_json();
  v02["V"] = 0.2;
  CHECK(capsule::choose_tau(Scene::from_json(v02, "t.json")) == Approx(1.5));
  // Never below 0.52, and a scene's own tau wins.
  CHECK(capsule::choose_tau(sphere(0.0001, 0.0, 2)) == Approx(0.52));
  json j = ref.to_json();
  j["resolution"]["tau"] = 1.0;
  CHECK(capsule::choose_tau(Scene::from_json(j, "t.json")) == 1.0);
}

TEST_CASE("3D relaxation-time rule: the Maxwell element's stiffness lowers tau", "[scene]") {
  // eta = 10, G = 50, the dissertation's reading of (63), Ca = 0.05, Re = 0.05: the bench's
  // eta10 member, which blew up at a = 4 and 5 with tau = 1.5 (docs/guide/model.md "Relaxation time").
  auto viscous = [](double a) {
    json j = json::parse(R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0, "V": 1, "eta": 10, "G": 50,
      "conventions": {"sls_viscosity": "dissertation"},
      "protocol": {"shear": {"until": "steady"}, "recover": {"until": "settled"}}})");
    j["resolution"] = {{"a", a}};
    return Scene::from_json(j, "t.json");
  };
  // By hand at a = 5, tau = 1.5: nu = 1/3, E_s = Re nu^2 / (a Ca) = 1/45, G_s = E_s / 3,
  // E_m = 50 G_s = 0.37037, tau_m = (eta a nu / 3) / E_m = 15 steps,
  // M = E_m tau_m (1 - exp(-1/15)) / nu = 1.0749.
  CHECK(capsule::maxwell_stiffness_number(viscous(5), 1.5) == Approx(1.0749).epsilon(1e-4));
  CHECK(capsule::maxwell_stiffness_number(viscous(5), 1.5) ==
        Approx(0.37037037 * 15.0 * (1.0 - std::exp(-1.0 / 15.0)) * 3.0).epsilon(1e-6));
  // Lowered to M = 0.15 with Roma's kernel (the default) at every a (M at tau 1.5: 1.32 / 1.07 /
  // 0.78 / 0.55 at a = 4 / 5 / 7 / 10); the larger a, the closer to 1.5 (E_m / nu falls as 1 / a).
  double previous = 0.5;
  for (double a : {4.0, 5.0, 7.0, 10.0}) {
    const double tau = capsule::choose_tau(viscous(a));
    INFO("a = " << a << ": tau " << tau);
    CHECK(tau < 1.5);
    CHECK(tau > previous);
    CHECK(capsule::maxwell_stiffness_bound(viscous(a)) == 0.15);
    CHECK(capsule::maxwell_stiffness_number(viscous(a), tau) == Approx(0.15).epsilon(1e-6));
    previous = tau;
  }
  // The roots of the hand formula, solved apart (bisection in Python): M = 0.15 at tau 0.6356
  // (a = 5) and 0.7706 (a = 10).
  CHECK(capsule::choose_tau(viscous(5)) == Approx(0.6356).epsilon(1e-3));
  CHECK(capsule::choose_tau(viscous(10)) == Approx(0.7706).epsilon(1e-3));
  // Peskin's kernel is stable at rest at M = 0.4 (docs/findings/accuracy_and_stability.md "A slow
  // instability at rest"): its bound stays 0.4, the root of the same formula at tau 0.8644 (a = 5).
  json peskin_json = viscous(5).to_json();
  peskin_json["resolution"]["kernel"] = "peskin4";
  const Scene peskin = Scene::from_json(peskin_json, "t.json");
  CHECK(capsule::maxwell_stiffness_bound(peskin) == 0.4);
  CHECK(capsule::choose_tau(peskin) == Approx(0.8644).epsilon(1e-3));
  CHECK(capsule::maxwell_stiffness_number(peskin, capsule::choose_tau(peskin)) == Approx(0.4).epsilon(1e-6));
  // A weak Maxwell element needs nothing: G = 2 at a = 10 has M(1.5) = 0.022.
  json weak = viscous(10).to_json();
  weak["G"] = 2.0;
  CHECK(capsule::maxwell_stiffness_number(Scene::from_json(weak, "t.json"), 1.5) < 0.4);
  CHECK(capsule::choose_tau(Scene::from_json(weak, "t.json")) == Approx(1.5));
  // No Maxwell element, no bound: the elastic sphere at a = 5 keeps 1.5.
  json elastic = viscous(5).to_json();
  elastic["eta"] = 0.0;
  CHECK(capsule::maxwell_stiffness_number(Scene::from_json(elastic, "t.json"), 1.5) == 0.0);
  CHECK(capsule::choose_tau(Scene::from_json(elastic, "t.json")) == Approx(1.5));
  // The power law in the membrane: its relaxation time grows where the membrane shears slowly,
  // so M = E_m / nu (K = 100 at Ca 0.05, a = 5: 50 G_s / nu = 1.111 at tau 1.5).
  json power = elastic;
  power["power_law"] = {{"K", 100.0}, {"n", 0.64}, {"model", "membrane"}};
  const Scene pl = Scene::from_json(power, "t.json");
  CHECK(capsule::maxwell_stiffness_number(pl, 1.5) == Approx(50.0 / 135.0 * 3.0).epsilon(1e-9));
  CHECK(capsule::maxwell_stiffness_number(pl, capsule::choose_tau(pl)) == Approx(0.15).epsilon(1e-6));
  // Where no tau reaches M_max the rule falls back to its floor 0.52: a Maxwell element of G =
  // 1e4 (the scene's largest) at eta = 10, physical reading, a = 5. At tau 0.52 (nu = 1/150):
  // E_s = Re nu^2 / (a Ca) = 8.889e-6, E_m = 1e4 E_s / 3 = 0.02963, tau_m = eta a nu / E_m =
  // 11.25 steps, M = E_m tau_m (1 - exp(-1/11.25)) / nu = 4.25 > 0.15.
  json stiff = viscous(5).to_json();
  stiff["G"] = 1e4;
  stiff["conventions"]["sls_viscosity"] = "physical";
  const Scene floor_scene = Scene::from_json(stiff, "t.json");
  CHECK(capsule::maxwell_stiffness_number(floor_scene, 0.52) == Approx(4.25).epsilon(2e-3));
  CHECK(capsule::choose_tau(floor_scene) == 0.52);
}

TEST_CASE("3D Maxwell element in lattice units: modulus and relaxation time", "[scene]") {
  json j = json::parse(R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0, "V": 1, "eta": 10, "G": 50,
    "resolution": {"a": 5}, "conventions": {"sls_viscosity": "dissertation"},
    "protocol": {"shear": {"until": "steady"}, "recover": {"until": "settled"}}})");
  // By hand at tau 1.5 (as above): E_m = 50 E_s / 3 = 0.37037, tau_m = (eta a nu / 3) / E_m = 15.
  const capsule::Units u = capsule::units_for(Scene::from_json(j, "t.json"), 1.5);
  const auto sls = capsule::maxwell_element_3d(Scene::from_json(j, "t.json"), u);
  CHECK(sls.present);
  CHECK_FALSE(sls.power_law);
  CHECK(sls.E_m == Approx(50.0 / 135.0).epsilon(1e-12));
  CHECK(sls.tau_m == Approx(15.0).epsilon(1e-12));
  // The physical reading: three times the surface viscosity, three times tau_m.
  j["conventions"]["sls_viscosity"] = "physical";
  CHECK(capsule::maxwell_element_3d(Scene::from_json(j, "t.json"), u).tau_m == Approx(45.0).epsilon(1e-12));
  // The power law in the membrane (which the scene allows only with eta = 0): tau_m = K a nu /
  // E_m at gamma = k (K = 100: 100 * 5 / 3 / 0.37037 = 450).
  j["eta"] = 0.0;
  j["power_law"] = {{"K", 100.0}, {"n", 0.64}, {"model", "membrane"}};
  const auto pl = capsule::maxwell_element_3d(Scene::from_json(j, "t.json"), u);
  CHECK(pl.power_law);
  CHECK(pl.tau_m == Approx(450.0).epsilon(1e-12));
  // No Maxwell element: absent.
  j.erase("power_law");
  CHECK_FALSE(capsule::maxwell_element_3d(Scene::from_json(j, "t.json"), u).present);
}

TEST_CASE("a 2D scene's canonical form does not depend on keys the 2D model ignores", "[scene]") {
  const json plain = Scene::from_json(minimal_2d(), "a").to_json();
  json j = minimal_2d();
  j["C"] = 100;
  j["G"] = 10;
  j["c0"] = -2.09;
  j["volume_penalty"] = 5;
  j["power_law"] = {{"n", 0.64}};
  j["resolution"] = {{"mesh_level", 6}, {"kernel", "peskin4"}};
  j["output"] = {{"snapshots", "vtk"}};
  CHECK(Scene::from_json(j, "b").to_json() == plain);
  // A 2D key still matters, and a 3D scene ignores segments instead.
  json k = minimal_2d();
  k["resolution"] = {{"segments", 200}};
  CHECK(Scene::from_json(k, "c").to_json() != plain);
  json three = minimal_2d();
  three["dim"] = 3;
  three["shape"] = "sphere";
  const json three_plain = Scene::from_json(three, "d").to_json();
  three["resolution"] = {{"segments", 200}};
  CHECK(Scene::from_json(three, "e").to_json() == three_plain);
  three["resolution"] = {{"mesh_level", 3}};
  CHECK(Scene::from_json(three, "f").to_json() != three_plain);
}

TEST_CASE("a 2D scene with a power-law membrane is refused at validation, as the run refuses it", "[scene]") {
  json j = minimal_2d();
  j["power_law"] = {{"K", 0.1}};
  CHECK_THROWS_WITH(Scene::from_json(j, "scenes/p.json"),
                    Catch::StartsWith("scenes/p.json: power_law.K: ") && Catch::Contains("3D model") &&
                        Catch::Contains("(allowed: 0 in 2D)"));
  j["dim"] = 3;
  j["shape"] = "sphere";
  CHECK_NOTHROW(Scene::from_json(j, "scenes/p.json"));
}
