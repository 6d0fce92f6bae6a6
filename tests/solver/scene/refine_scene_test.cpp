// resolution.refine (docs/guide/refinement.md "In a scene"): read, written to the canonical scene
// only when given (so no other member id moves), and refused with the file, the key and the
// allowed range where the refined fluid cannot run the scene.
#include <catch2/catch.hpp>

#include <cmath>

#include "solver/scene/refined_block_extent.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

nlohmann::json sphere(double a = 10) {
  return {{"dim", 3}, {"shape", "sphere"}, {"Ca", 0.05}, {"E_b", 0}, {"V", 1}, {"eta", 0},
          {"resolution", {{"a", a}, {"mesh_level", 3}}},
          {"protocol", {{"shear", {{"until", "time"}, {"kt", 1}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}}};
}

}  // namespace

TEST_CASE("resolution.refine is read and written only when given", "[scene][refine]") {
  nlohmann::json j = sphere();
  const Scene plain = Scene::from_json(j, "t.json");
  CHECK_FALSE(plain.resolution.refine);
  CHECK_FALSE(plain.to_json()["resolution"].contains("refine"));
  j["resolution"]["refine"] = {{"margin", 0.8}};
  const Scene s = Scene::from_json(j, "t.json");
  REQUIRE(s.resolution.refine);
  CHECK(s.resolution.refine->levels == 1);
  CHECK(s.resolution.refine->margin == 0.8);
  // A refined 3D scene defaults to double precision (its first members ran so); single is a choice.
  CHECK(s.resolution.precision == lbm::Precision::double_precision);
  CHECK(plain.resolution.precision == lbm::Precision::single_precision);
  j["resolution"]["precision"] = "single";
  const Scene single = Scene::from_json(j, "t.json");
  CHECK(single.resolution.precision == lbm::Precision::single_precision);
  CHECK(single.to_json()["resolution"]["precision"] == "single");
  j["resolution"].erase("precision");
  const nlohmann::json canonical = s.to_json();
  CHECK(canonical["resolution"]["refine"] == nlohmann::json({{"levels", 1}, {"margin", 0.8}}));
  // The canonical text reads back to the same scene.
  CHECK(Scene::from_json(canonical, "c.json").to_json() == canonical);
}

TEST_CASE("the refined block is a cube about the centre that spans x and z where it would reach the box's ends", "[scene][refine]") {
  nlohmann::json j = sphere(10);
  j["resolution"]["refine"] = {{"margin", 0.6}};
  const Scene s = Scene::from_json(j, "t.json");
  const RefinedBlockPlan p = refined_block_extent(s);
  REQUIRE(p.why.empty());
  // Domain 10 x 10 x 8 a (100 x 100 x 80 fine nodes, 50 x 50 x 40 coarse cells); the sphere's
  // markers at r_m = a - inset, the cube's half-width r_m + 6 fine spacings.
  const double half = start_shape_radius(s) + 6.0;
  CHECK(start_shape_radius(s) < 10.0);
  CHECK(start_shape_radius(s) > 8.0);
  for (int d = 0; d < 3; ++d) {
    const double c = d == 2 ? 40.0 : 50.0;
    CHECK(p.extent.begin[d] == int(std::floor(0.5 * (c - half))));
    CHECK(p.extent.end[d] == int(std::ceil(0.5 * (c + half))));
  }
  // A margin that reaches the box's ends in x and z, but not the walls, spans x and z.
  nlohmann::json wide = sphere(10);
  wide["resolution"]["domain"] = {3.2, 10, 3.2};
  wide["resolution"]["refine"] = {{"margin", 1.0}};
  const RefinedBlockPlan w = refined_block_extent(Scene::from_json(wide, "t.json"));
  CHECK(w.extent.begin[0] == 0);
  CHECK(w.extent.end[0] == 16);
  CHECK(w.extent.begin[2] == 0);
  CHECK(w.extent.end[2] == 16);
  CHECK(w.extent.begin[1] > 3);
  // The biconcave cell's rim lies beyond its equivalent radius.
  nlohmann::json b = sphere(10);
  b["shape"] = "biconcave";
  b["law"] = "skalak";
  b["resolution"]["refine"] = {{"margin", 0.6}};
  CHECK(start_shape_radius(Scene::from_json(b, "t.json")) > 1.2 * start_shape_radius(s));
}

TEST_CASE("resolution.refine refuses what the refined fluid cannot run, naming the file, key and range", "[scene][refine]") {
  auto refused = [](nlohmann::json j, const std::string& where) {
    INFO(j.dump());
    CHECK_THROWS_WITH(Scene::from_json(j, "r.json"), Catch::StartsWith("r.json: " + where));
  };
  nlohmann::json j = sphere();
  j["resolution"]["refine"] = {{"margin", 0.1}};  // below the roma3 kernel's reach, (0.5 + 1.5) / a = 0.2
  refused(j, "resolution.refine.margin: value 0.1 out of range (allowed: [0.2, 4])");
  j["resolution"]["refine"] = {{"margin", 3.5}};  // the cube would come within three coarse cells of a wall
  refused(j, "resolution.refine.margin: the block");
  CHECK_THROWS_WITH(Scene::from_json(j, "r.json"), Catch::Contains("(allowed: [0.2, 3.") && Catch::Contains("] in this channel)"));
  j["resolution"]["refine"] = {{"levels", 2}};
  refused(j, "resolution.refine.levels: value 2 out of range (allowed: integer in [1, 1])");
  j["resolution"]["refine"] = {{"margn", 1}};
  refused(j, "resolution.refine.margn");
  j = sphere();
  j["resolution"]["refine"] = nlohmann::json::object();
  j["V"] = 5;
  refused(j, "resolution.refine: the viscosity contrast (V = 5) is not built on the refined block yet");
  j["V"] = 1;
  j["power_law"] = {{"K", 2}, {"n", 0.7}, {"model", "fluid_shell"}};
  refused(j, "resolution.refine: the power law's fluid shell");
  j.erase("power_law");
  j["resolution"]["domain"] = {10.05, 10, 8};  // 100.5 -> 101 fine nodes along x
  refused(j, "resolution.refine: the domain holds 101 fine nodes along x");
  nlohmann::json two = {{"dim", 2}, {"shape", "circle"}, {"Ca", 0.05}, {"E_b", 0}, {"V", 1}, {"eta", 0},
                        {"resolution", {{"refine", nlohmann::json::object()}}},
                        {"protocol", {{"shear", {{"until", "time"}, {"kt", 1}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}}};
  refused(two, "resolution.refine: the refined block is built for the 3D fluid only (allowed: no refine key in 2D)");
}
