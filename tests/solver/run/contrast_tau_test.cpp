// resolution.collision = trt keeps a viscosity-contrast member independent of the relaxation
// time: a V = 5 sphere (Ca 0.05, E_b 0) at CI size (a = 4, mesh level 2, shear to kt = 1) at
// tau 0.7 and 1.5 (inside: 1.5 and 5.5). Measured D_xy(kt = 1):
//   trt: 0.145507 / 0.146006 (+0.34 %);  mrt (the text's rates): 0.147035 / 0.167754 (+14.1 %).
// Bound 1 % for trt: the target at a = 7 over tau 0.7-1.5 (docs/findings/accuracy_and_stability.md
// "Viscosity contrast and the relaxation time"); what is left at this size is the V = 1 member's
// own tau dependence early in the transient. The mrt member at tau 1.5 must differ from the trt
// one by more than 5 % (measured +14.9 %), so the key reaches the fluid.
#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

double D_at_end(double tau, const std::string& collision) {
  omp_set_num_threads(1);  // as capsule3d_test.cpp: the 2-core CI machine
  nlohmann::json j = nlohmann::json::parse(R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0, "V": 5, "eta": 0,
    "resolution": {"a": 4, "mesh_level": 2},
    "protocol": {"shear": {"until": "time", "kt": 1}, "recover": {"until": "time", "kt": 0}},
    "output": {"interval_kt": 0.05}})");
  j["resolution"]["tau"] = tau;
  j["resolution"]["collision"] = collision;
  const Scene scene = Scene::from_json(j, "contrast_tau_test.json");
  const std::string path =
      (std::filesystem::temp_directory_path() / ("contrast_tau_test_" + collision + std::to_string(tau) + ".h5")).string();
  {
    io::MemberWriter out(path);
    out.finish(run_simulation3d(scene, out, true));
  }
  const io::MemberData d = io::read_member(path);
  std::filesystem::remove(path);
  REQUIRE(d.status == "complete");
  return d.series.at("D_xy").back();
}

}  // namespace

TEST_CASE("resolution.collision = trt: a V = 5 sphere's D_xy does not move with tau", "[capsule3d]") {
  const double lo = D_at_end(0.7, "trt"), hi = D_at_end(1.5, "trt"), mrt = D_at_end(1.5, "mrt");
  INFO("D_xy(kt = 1): trt tau 0.7 " << lo << ", tau 1.5 " << hi << "; mrt tau 1.5 " << mrt);
  CHECK(std::abs(hi - lo) < 0.01 * lo);
  CHECK(mrt > 1.05 * hi);
}
