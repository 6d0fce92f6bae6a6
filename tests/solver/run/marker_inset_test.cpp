// resolution.marker_inset places the 3D membrane's markers on the radius a - inset (the
// reference shape with them), 0 keeps them on a, and the default rule "stresslet" puts them on
// the radius solver/ib/hydrodynamic_radius.hpp computes: the mean distance of the shape's vertices
// from their centroid after a few steps, against the radius asked for. The membrane has moved
// by O(k dt) = 1e-3 a in those steps, so 0.01 lattice units separates an inset of 0.5 from none.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

io::MemberData short_member(const nlohmann::json& inset, double E_b = 0) {
  nlohmann::json j = nlohmann::json::parse(R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0, "V": 1, "eta": 0,
    "resolution": {"a": 5, "mesh_level": 2},
    "protocol": {"shear": {"until": "time", "kt": 0.004}, "recover": {"until": "time", "kt": 0}},
    "output": {"interval_kt": 0.002, "shapes_at_kt": [0.002]}})");
  if (!inset.is_null()) j["resolution"]["marker_inset"] = inset;
  j["E_b"] = E_b;
  const Scene scene = Scene::from_json(j, "marker_inset_test.json");
  const std::string path = (std::filesystem::temp_directory_path() / "marker_inset_test.h5").string();
  {
    io::MemberWriter out(path);
    out.finish(run_simulation3d(scene, out, true));
  }
  const io::MemberData d = io::read_member(path);
  std::filesystem::remove(path);
  REQUIRE(d.status == "complete");
  return d;
}

double mean_radius(const nlohmann::json& inset) {
  const io::MemberData d = short_member(inset);
  REQUIRE(!d.shapes.empty());
  const std::vector<double>& x = d.shapes.front().xyz;
  const std::size_t n = x.size() / 3;
  double c[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) c[k] += x[3 * i + k] / n;
  double r = 0;
  for (std::size_t i = 0; i < n; ++i) r += std::hypot(x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]) / n;
  return r;
}

}  // namespace

TEST_CASE("resolution.marker_inset puts the 3D markers on the radius a - inset", "[capsule3d]") {
  CHECK(std::abs(mean_radius(0.0) - 5.0) < 0.01);
  CHECK(std::abs(mean_radius(0.5) - 4.5) < 0.01);
  // The 3D default is the stresslet's rule: 0.53 at a = 5 with the default kernel roma3.
  CHECK(std::abs(mean_radius(nlohmann::json()) - (5.0 - 0.5263)) < 0.01);
  CHECK(std::abs(mean_radius("stresslet") - (5.0 - 0.5263)) < 0.01);
}

TEST_CASE("an inset membrane bends with the bending number of its own sphere: E_B = E_b r_m^2 E_s", "[capsule3d]") {
  // Bending against shear elasticity is E_B / (E_s r_m^2): with E_B = E_b a^2 E_s an inset
  // membrane bent as if E_b were (a / r_m)^2 larger, and the reference member's ladder rose by
  // 8 % from a = 5 to the limit (docs/findings/immersed_boundary_error_budget.md).
  const io::MemberData on_a = short_member(0.0, 0.025), inset = short_member(0.5, 0.025);
  CHECK(inset.attributes.at("marker_radius").get<double>() == Approx(4.5));
  CHECK(inset.attributes.at("E_B").get<double>() / on_a.attributes.at("E_B").get<double>() == Approx(0.81).epsilon(1e-12));
}
