// power_law.model "membrane" in a whole 3D member: at n = 1 the power-law membrane is the
// Kelvin-Voigt membrane of the same surface viscosity (the standard linear solid with eta = K in
// the physical reading), whatever the lattice, because the viscosity now lives in the membrane
// and not in a shell of lattice nodes (the text's (103)-(104), power_law.model "fluid_shell").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

nlohmann::json small_sphere(double a, int level, double tau = 1.5) {
  return {{"dim", 3}, {"shape", "sphere"}, {"Ca", 0.1}, {"E_b", 0}, {"V", 1}, {"eta", 0},
          {"resolution", {{"a", a}, {"mesh_level", level}, {"tau", tau}}},
          {"protocol", {{"shear", {{"until", "time"}, {"kt", 0.5}}}, {"recover", {{"until", "time"}, {"kt", 0.2}}}}},
          {"output", {{"interval_kt", 0.05}}}};
}

std::vector<double> deformation(const nlohmann::json& j, const std::string& name) {
  const Scene scene = Scene::from_json(j, name + ".json");
  const std::string path = (std::filesystem::temp_directory_path() / ("power_law_membrane_" + name + ".h5")).string();
  {
    io::MemberWriter out(path);
    out.finish(run_simulation3d(scene, out, true));
  }
  const io::MemberData d = io::read_member(path);
  std::filesystem::remove(path);
  REQUIRE(d.status == "complete");
  return d.series.at("D_xy");
}

}  // namespace

TEST_CASE("a membrane power law with n = 1 is the Kelvin-Voigt membrane of the same surface viscosity", "[capsule3d]") {
  // Both tau 1.5 (the 3D rule) and tau 0.7: the shell reading moved 37 % between these
  // (docs/findings/probes.md); the membrane reading is the same member step for step, so the
  // series agree to round-off (1e-12 of D: the same operations, perhaps contracted differently).
  for (double tau : {1.5, 0.7}) {
    nlohmann::json kv = small_sphere(4, 2, tau);
    kv["eta"] = 10;
    nlohmann::json power = small_sphere(4, 2, tau);
    power["power_law"] = {{"K", 10}, {"n", 1}, {"model", "membrane"}};
    const std::vector<double> d_kv = deformation(kv, "kv"), d_power = deformation(power, "power");
    REQUIRE(d_kv.size() == d_power.size());
    REQUIRE(d_kv.size() > 10);
    CHECK(d_kv.back() > 0.05);  // it deformed
    for (std::size_t i = 0; i < d_kv.size(); ++i) REQUIRE(std::abs(d_kv[i] - d_power[i]) <= 1e-12 * std::max(1.0, d_kv[i]));
  }
}

TEST_CASE("a shear-thinning membrane power law does not move with the fluid's relaxation time, and little with a", "[capsule3d]") {
  // n = 0.64, K = 10, Ca 0.1: D_xy at kt 0.5 (row 10 of 0.05 kt). Measured 2026-12-05: tau 1.5
  // against 0.7 at a = 4, 0.0516 / 0.0516 (0.1 %; the fluid shell 0.0660 / 0.0361, -45 %, the
  // Kelvin-Voigt member at eta = 10 -0.7 %); the tolerance, 1.5 %, is twice the largest
  // such change of the Kelvin-Voigt member at a = 4-5. a = 4 against a = 5 (level 2 both):
  // -4.7 % (the shell +12.7 %, the Kelvin-Voigt member -1.3 %); the shear-thinning law, floored
  // at 0.01 k where the membrane starts from rest, amplifies the solver's own resolution error
  // of the Kelvin-Voigt member 3-4 fold (docs/findings/accuracy_and_stability.md "Power law in
  // the membrane"), so the bound is 8 %, which the shell fails in size and sign.
  auto power = [](double a, double tau) {
    nlohmann::json j = small_sphere(a, 2, tau);
    j["power_law"] = {{"K", 10}, {"n", 0.64}, {"model", "membrane"}};
    return j;
  };
  const double d_a4 = deformation(power(4, 1.5), "a4").at(10);
  const double d_a4_tau = deformation(power(4, 0.7), "a4_tau").at(10);
  const double d_a5 = deformation(power(5, 1.5), "a5").at(10);
  CHECK(d_a4 > 0.03);  // it deformed
  CHECK(std::abs(d_a4_tau / d_a4 - 1) < 0.015);
  CHECK(std::abs(d_a5 / d_a4 - 1) < 0.08);
}
